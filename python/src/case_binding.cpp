// vibroimpact.Case: a checked case, read from a file, a TOML string or a dict, whose numbers can be
// read and changed by the paths of `sweep --set` (sweep/case_paths.hpp).

#include <cstdint>
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

// Sets every (path, value) on a copy of c, then checks the copy as a case file is checked; c is
// changed only when all is well.
void set_values(Case& c, const std::vector<std::pair<std::string, double>>& values) {
    Case changed = c;
    for (const auto& [text, value] : values) set_case_value(changed, resolve_case_path(text, changed), value);
    const std::vector<CaseProblem> problems = check_case(changed);
    if (!problems.empty()) throw locate_in_case(changed, InputError(problems.front().key + ": " + problems.front().message));
    c = std::move(changed);
}

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
            "set", [](Case& c, const std::string& path, double value) { set_values(c, {{path, value}}); },
            py::arg("path"), py::arg("value"),
            "Sets the value at a path (as `sweep --set PATH=VALUE`, SI units) and checks the case; on InputError "
            "the case is unchanged")
        .def(
            "update",
            [](Case& c, const py::dict& values) {
                std::vector<std::pair<std::string, double>> v;
                for (const auto& [k, x] : values) v.emplace_back(py::str(k).cast<std::string>(), x.cast<double>());
                set_values(c, v);
            },
            py::arg("values"), "Sets several {path: value} together, then checks the case once")
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
