// vibroimpact.Case: a checked case, read from a file, a TOML string or a dict, whose numbers can be
// read and changed by the paths of `sweep --set` (sweep/case_paths.hpp).

#include <cstdint>
#include <stdexcept>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "io/case_reader.hpp"
#include "io/case_writer.hpp"
#include "io/number_text.hpp"
#include "model/case_checks.hpp"
#include "model/input_error.hpp"
#include "sweep/case_paths.hpp"

namespace vi::python {
namespace {

toml::table toml_table(const py::handle& dict, const std::string& where);

using TomlValue = std::variant<bool, std::int64_t, double, std::string, toml::table, toml::array>;

// One value of a case dict as TOML: bool, int, float, str, a list or a nested dict.
TomlValue toml_value(const py::handle& v, const std::string& where) {
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
    if (py::isinstance<py::int_>(v)) return v.cast<std::int64_t>();
    if (py::isinstance<py::float_>(v)) return v.cast<double>();
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::isinstance<py::dict>(v)) return toml_table(v, where);
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
        toml::array a;
        std::size_t i = 0;
        for (const py::handle item : v) {
            std::visit([&](auto&& x) { a.push_back(std::move(x)); },
                       toml_value(item, where + "[" + std::to_string(i++) + "]"));
        }
        return a;
    }
    throw InputError(where + ": cannot be written as TOML (a " +
                     py::str(py::type::of(v).attr("__name__")).cast<std::string>() + ")");
}

toml::table toml_table(const py::handle& dict, const std::string& where) {
    toml::table t;
    for (const auto& [k, v] : dict.cast<py::dict>()) {
        const std::string key = py::str(k).cast<std::string>();
        std::visit([&](auto&& x) { t.insert(key, std::move(x)); }, toml_value(v, where.empty() ? key : where + "." + key));
    }
    return t;
}

// A value of set or update as `--set` takes one: a text ("0.5 um", "2e-6") as is, a number in SI
// units as the shortest text that reads back the same double.
std::string set_text_of(const std::string& path, const py::handle& v) {
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::isinstance<py::bool_>(v) || !(py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v) || py::hasattr(v, "__float__"))) {
        throw InputError(path + ": a number (SI units) or a text with its unit such as \"0.5 um\", not a " +
                         py::str(py::type::of(v).attr("__name__")).cast<std::string>());
    }
    return round_trip_text(v.cast<double>());
}

// Sets every (path, value) on a copy of c, then checks the copy as a case file is checked; c is
// changed only when all is well. An error is placed at the key's line in the case's file.
void set_values(Case& c, const std::vector<std::pair<std::string, std::string>>& values) {
    Case changed = c;
    try {
        for (const auto& [path, text] : values) set_case_text(changed, path, text);
    } catch (const InputError& e) {
        throw locate_in_case(c, e);
    }
    const std::vector<CaseProblem> problems = check_case(changed);
    if (!problems.empty()) throw locate_in_case(changed, InputError(problems.front().key + ": " + problems.front().message));
    c = std::move(changed);
}

// A TOML value as the Python value tomllib would give (tables as dicts, arrays as lists).
py::object python_value(const toml::node& n) {
    if (const auto* t = n.as_table()) {
        py::dict d;
        for (const auto& [k, v] : *t) d[py::str(std::string(k.str()))] = python_value(v);
        return d;
    }
    if (const auto* a = n.as_array()) {
        py::list l;
        for (const toml::node& v : *a) l.append(python_value(v));
        return l;
    }
    if (const auto* s = n.as_string()) return py::str(s->get());
    if (const auto* i = n.as_integer()) return py::int_(i->get());
    if (const auto* f = n.as_floating_point()) return py::float_(f->get());
    if (const auto* b = n.as_boolean()) return py::bool_(b->get());
    throw std::logic_error("case_to_toml wrote a date or time");
}

py::dict case_dict(const Case& c) { return python_value(toml::parse(case_to_toml(c))).cast<py::dict>(); }

py::object value_at(const Case& c, const std::string& text) {
    const CasePath p = resolve_case_path(text, c);
    const double v = get_case_value(c, p);
    if (is_integer_path(p)) return py::int_(static_cast<long long>(v));
    return py::float_(v);
}

}  // namespace

void bind_case(py::module_& m) {
    py::class_<Case>(m, "Case", "A checked case (what a case file holds), in SI units")
        .def_static("from_file", &read_case_file, py::arg("path"),
                    "Reads and checks a TOML case file; InputError names the file, line and key")
        .def_static("from_string", &read_case_text, py::arg("text"), py::arg("source") = "<string>",
                    "Reads a case from TOML text; `source` stands for the file in messages, and files the "
                    "case names (load tables) are found next to it")
        .def_static(
            "from_dict",
            [](const py::dict& data, const std::string& source) {
                std::ostringstream text;
                text << toml_table(data, "");
                return read_case_text(text.str(), source);
            },
            py::arg("data"), py::arg("source") = "<dict>",
            "Reads a case from a dict shaped as the TOML file (tables as dicts, [[supports]] as a list of dicts); "
            "messages give the key, and lines of the TOML text the dict is written as")
        .def_property_readonly("name", [](const Case& c) { return c.name; }, "The case's name")
        .def_property_readonly(
            "file", [](const Case& c) { return c.origin.file; }, "Where the case was read from (or its source name)")
        .def("get", &value_at, py::arg("path"),
             "The value at a path such as 'supports[0].gap', in SI units (int for whole-number paths)")
        .def(
            "set", [](Case& c, const std::string& path, const py::object& value) { set_values(c, {{path, set_text_of(path, value)}}); },
            py::arg("path"), py::arg("value"),
            "Sets the value at a path: a number in SI units or a text as `--set` takes it (\"0.5 um\"); checks the case; "
            "on InputError the case is unchanged")
        .def(
            "update",
            [](Case& c, const py::dict& values) {
                std::vector<std::pair<std::string, std::string>> v;
                for (const auto& [k, x] : values) {
                    const std::string path = py::str(k).cast<std::string>();
                    v.emplace_back(path, set_text_of(path, x));
                }
                set_values(c, v);
            },
            py::arg("values"), "Sets several {path: value} together, then checks the case once")
        .def("to_dict", &case_dict, "The case as the dict of its TOML file (to_toml), values in SI units")
        .def("to_toml", &case_to_toml,
             "The case as a case file: every key in effect with its value, in SI units (reads back as the same case)")
        .def("copy", [](const Case& c) { return Case(c); }, "An independent copy")
        .def("__copy__", [](const Case& c) { return Case(c); })
        .def("__deepcopy__", [](const Case& c, const py::dict&) { return Case(c); }, py::arg("memo"))
        .def("__repr__",
             [](const Case& c) { return "<vibroimpact.Case '" + c.name + "' from " + c.origin.file + ">"; })
        .def_static("paths", &case_path_forms,
                    "Every path accepted by get, set and sweep (i: support or load number from 0, k: 0 or 1)");
}

}  // namespace vi::python
