#include "io/case_reader.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "io/input_error.hpp"
#include "io/toml_fields.hpp"
#include "io/units.hpp"
#include "model/case_checks.hpp"

// Reading happens in two passes. The first reads the TOML tree into a Case, one function per table,
// and collects every problem with the text (unknown or missing key, wrong type, bad unit, value not
// finite) at its position; the earliest in the file is thrown. Only when the text is clean does the
// second pass check the values (check_case plus the few checks made while reading), each problem
// placed at the line of the key it names, and again the earliest is thrown. To add a table, write a
// read_<table> function and call it from read_root with its key in the root's accepted list.

namespace vi {
namespace {

using tomlio::FieldReader;
using tomlio::Position;
using tomlio::ReadLog;

// What reading found besides the Case itself.
struct Reading {
    ReadLog log;                              // problems with the text; where each key stands
    std::vector<CaseProblem> value_problems;  // problems with values, reported with check_case's
};

int clamp_to_int(std::int64_t v) {
    constexpr std::int64_t lo = std::numeric_limits<int>::min();
    constexpr std::int64_t hi = std::numeric_limits<int>::max();
    return static_cast<int>(std::clamp(v, lo, hi));
}

EndCondition end_condition(const std::string& s) {
    if (s == "pinned") return EndCondition::pinned;
    if (s == "free") return EndCondition::free;
    return EndCondition::clamped;
}

// A sub-table of f's table and its position (its header line), or nullptr when absent or not a table.
const toml::table* sub_table(FieldReader& f, std::string_view key, bool required, Position& at) {
    const toml::table* t = f.table(key, required);
    if (t != nullptr) at = tomlio::position_of(t->source(), f.key_position(key));
    return t;
}

// The array under key when it holds exactly two elements; else nullptr (problem logged).
const toml::array* pair_array(FieldReader& f, std::string_view key, const std::string& what) {
    const std::string expected = "an array of 2 " + what;
    const toml::array* a = f.array(key, false, expected);
    if (a == nullptr) return nullptr;
    if (a->size() != 2) {
        f.reject(key, "expected " + expected + ", got " + std::to_string(a->size()) + " element(s)");
        return nullptr;
    }
    return a;
}

std::string element_path(const FieldReader& f, std::string_view key, std::size_t i) {
    return tomlio::child_path(f.path(), key) + "[" + std::to_string(i) + "]";
}

Position element_position(const FieldReader& f, std::string_view key, const toml::node& element) {
    return tomlio::position_of(element.source(), f.key_position(key));
}

// Two dimensionless numbers under key.
std::optional<std::array<double, 2>> number_pair(FieldReader& f, std::string_view key, ReadLog& log) {
    const toml::array* a = pair_array(f, key, "numbers");
    if (a == nullptr) return std::nullopt;
    std::array<double, 2> out{};
    bool ok = true;
    for (std::size_t i = 0; i < 2; ++i) {
        const toml::node& e = *a->get(i);
        const auto v = tomlio::read_quantity(e, Dimension::dimensionless, element_path(f, key, i),
                                             element_position(f, key, e), log);
        if (v) out[i] = *v;
        ok = ok && v.has_value();
    }
    if (!ok) return std::nullopt;
    return out;
}

// Two integers under key.
std::optional<std::array<int, 2>> integer_pair(FieldReader& f, std::string_view key, ReadLog& log) {
    const toml::array* a = pair_array(f, key, "integers");
    if (a == nullptr) return std::nullopt;
    std::array<int, 2> out{};
    bool ok = true;
    for (std::size_t i = 0; i < 2; ++i) {
        const toml::node& e = *a->get(i);
        const auto v = tomlio::read_integer(e, element_path(f, key, i), element_position(f, key, e), log);
        if (v) out[i] = clamp_to_int(*v);
        ok = ok && v.has_value();
    }
    if (!ok) return std::nullopt;
    return out;
}

void read_beam(const toml::table& t, Position at, Reading& r, Beam& beam) {
    FieldReader f(t, "beam", at, r.log, {"length", "width", "thickness", "elements", "left", "right"});
    if (auto v = f.quantity("length", Dimension::length, true)) beam.length = *v;
    if (auto v = f.quantity("width", Dimension::length, true)) beam.width = *v;
    if (auto v = f.quantity("thickness", Dimension::length, true)) beam.thickness = *v;
    // Out-of-int values are clamped so that check_case reports them as too small or too large.
    if (auto v = f.integer("elements", true)) beam.elements = clamp_to_int(*v);
    if (auto v = f.choice("left", {"clamped", "pinned", "free"}, false)) beam.left = end_condition(*v);
    if (auto v = f.choice("right", {"clamped", "pinned", "free"}, false)) beam.right = end_condition(*v);
    f.finish();
}

void read_material(const toml::table& t, Position at, Reading& r, Material& m) {
    FieldReader f(t, "material", at, r.log, {"youngs_modulus", "density", "poisson_ratio", "plate_modulus"});
    if (auto v = f.quantity("youngs_modulus", Dimension::pressure, true)) m.youngs_modulus = *v;
    if (auto v = f.quantity("density", Dimension::density, true)) m.density = *v;
    if (auto v = f.quantity("poisson_ratio", Dimension::dimensionless, true)) m.poisson_ratio = *v;
    if (auto v = f.boolean("plate_modulus", false)) m.plate_modulus = *v;
    f.finish();
}

void read_damping(const toml::table& t, Position at, Reading& r, RayleighDamping& d) {
    FieldReader f(t, "damping", at, r.log, {"ratios", "modes", "alpha", "beta"});
    f.exclusive("ratios", "alpha");
    f.exclusive("ratios", "beta");
    if (f.has("ratios")) {
        d.from_ratios = true;
        if (auto v = number_pair(f, "ratios", r.log)) {
            d.ratio1 = (*v)[0];
            d.ratio2 = (*v)[1];
        }
        if (auto v = integer_pair(f, "modes", r.log)) {
            d.mode1 = (*v)[0];
            d.mode2 = (*v)[1];
        }
    } else {
        if (f.has("modes")) f.reject("modes", "needs damping.ratios (the modes the ratios refer to)");
        if (auto v = f.quantity("alpha", Dimension::mass_damping, false)) d.alpha = *v;
        if (auto v = f.quantity("beta", Dimension::time, false)) d.beta = *v;
    }
    f.finish();
}

Support read_support(const toml::table& t, const std::string& path, Position at, Reading& r) {
    FieldReader f(t, path, at, r.log,
                  {"position", "side", "gap", "prestress", "stiffness", "damping", "damping_ratio"});
    Support s;
    if (auto v = f.quantity("position", Dimension::dimensionless, true)) s.position = *v;
    if (auto v = f.choice("side", {"below", "above"}, false)) s.side = (*v == "above") ? Side::above : Side::below;
    f.exclusive("gap", "prestress");
    if (auto v = f.quantity("gap", Dimension::length, false)) {
        s.surface = -*v;
        if (*v < 0.0) r.value_problems.push_back({path + ".gap", "must not be negative"});
    }
    if (auto v = f.quantity("prestress", Dimension::length, false)) {
        s.surface = *v;
        if (*v < 0.0) r.value_problems.push_back({path + ".prestress", "must not be negative"});
    }
    if (auto v = f.quantity("stiffness", Dimension::stiffness, true)) s.stiffness = *v;
    f.exclusive("damping", "damping_ratio");
    if (auto v = f.quantity("damping", Dimension::damping, false)) s.damping = *v;
    if (auto v = f.quantity("damping_ratio", Dimension::dimensionless, false)) s.damping_ratio = *v;
    f.finish();
    return s;
}

void read_supports(const toml::array& a, Position at, Reading& r, std::vector<Support>& out) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        const toml::node& entry = *a.get(i);
        const std::string path = "supports[" + std::to_string(i) + "]";
        const Position p = tomlio::position_of(entry.source(), at);
        const toml::table* t = entry.as_table();
        if (t == nullptr) {
            r.log.problem(p, path, "expected a table (a [[supports]] entry), got " + tomlio::type_name(entry));
            continue;
        }
        out.push_back(read_support(*t, path, p, r));
    }
}

Case read_root(const toml::table& root, const std::string& default_name, Reading& r) {
    FieldReader f(root, "", Position{}, r.log, {"name", "beam", "material", "damping", "supports"});
    Case c;
    c.name = default_name;
    if (auto v = f.string("name", false)) {
        c.name = *v;
        if (v->empty()) r.value_problems.push_back({"name", "must not be empty"});
    }
    Position at;
    if (const auto* t = sub_table(f, "beam", true, at)) read_beam(*t, at, r, c.beam);
    if (const auto* t = sub_table(f, "material", true, at)) read_material(*t, at, r, c.material);
    if (const auto* t = sub_table(f, "damping", false, at)) read_damping(*t, at, r, c.damping);
    if (const auto* a = f.array("supports", false, "an array of tables ([[supports]])")) {
        read_supports(*a, f.key_position("supports"), r, c.supports);
    }
    f.finish();
    return c;
}

// Escapes line breaks so that every message is one line, whatever the file name or text holds.
std::string one_line(std::string s) {
    std::string out;
    for (const char ch : s) {
        if (ch == '\n') {
            out += "\\n";
        } else if (ch == '\r') {
            out += "\\r";
        } else {
            out += ch;
        }
    }
    return out;
}

[[noreturn]] void throw_problem(const std::string& source, const tomlio::SourceProblem& p) {
    throw InputError(one_line(source + ":" + std::to_string(p.at.line) + ": " + p.key + ": " + p.message));
}

std::string default_name(const std::string& source_name) {
    std::string stem = std::filesystem::path(source_name).stem().string();
    return stem.empty() ? "case" : stem;
}

}  // namespace

Case read_case_text(const std::string& text, const std::string& source_name) {
    toml::table root;
    try {
        root = toml::parse(std::string_view(text), std::string_view(source_name));
    } catch (const toml::parse_error& e) {
        const auto line = e.source().begin.line;
        const std::string where = line > 0 ? source_name + ":" + std::to_string(line) : source_name;
        throw InputError(one_line(where + ": TOML syntax: " + std::string(e.description())));
    }

    Reading r;
    Case c = read_root(root, default_name(source_name), r);
    if (auto p = r.log.first()) throw_problem(source_name, *p);

    std::vector<CaseProblem> problems = r.value_problems;
    for (CaseProblem& p : check_case(c)) problems.push_back(std::move(p));
    ReadLog placed;
    for (const CaseProblem& p : problems) placed.problem(r.log.where(p.key), p.key, p.message);
    if (auto p = placed.first()) throw_problem(source_name, *p);
    return c;
}

Case read_case_file(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw InputError(one_line(path + ": cannot read file (it is a directory)"));
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        const std::string reason = err != 0 ? " (" + std::generic_category().message(err) + ")" : "";
        throw InputError(one_line(path + ": cannot read file" + reason));
    }
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw InputError(one_line(path + ": cannot read file (read error)"));
    return read_case_text(text, path);
}

}  // namespace vi
