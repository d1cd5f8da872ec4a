#include "io/case_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "model/input_error.hpp"
#include "io/air_reader.hpp"
#include "io/electrode_reader.hpp"
#include "io/load_table.hpp"
#include "io/text_file.hpp"
#include "io/toml_fields.hpp"
#include "io/units.hpp"
#include "model/case_checks.hpp"

// Reading happens in two passes. The first reads the TOML tree into a Case, one function per table,
// and collects every problem with the text (unknown or missing key, wrong type, bad unit, value not
// finite) at its position; the earliest in the file is thrown. Only when the text is clean does the
// load tables named by [[loads]] get read (CSV files: their first bad line is thrown) and the second
// pass checks the values (check_case plus the few checks made while reading), each problem placed at
// the line of the key it names, and again the earliest is thrown. To add a table, write a
// read_<table> function and call it from read_root with its key in the root's accepted list.

namespace vi {
namespace {

using tomlio::clamp_to_int;
using tomlio::FieldReader;
using tomlio::integer_pair;
using tomlio::number_pair;
using tomlio::only_with;
using tomlio::Position;
using tomlio::ReadLog;

// A [[loads]] or [[electrodes]] entry whose time function is a CSV table, read once the case text
// is clean.
struct TableFile {
    std::size_t load = 0;    // index into Case::loads (or Case::electrodes)
    std::string file;        // as written in the case file
    bool electrode = false;  // an electrode's voltage table (columns t_s,V_V)
};

// What reading found besides the Case itself.
struct Reading {
    ReadLog log;                              // problems with the text; where each key stands
    std::vector<CaseProblem> value_problems;  // problems with values, reported with check_case's
    std::vector<TableFile> tables;
};

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

void read_beam(const toml::table& t, Position at, Reading& r, Beam& beam) {
    FieldReader f(t, "beam", at, r.log, {"length", "width", "thickness", "elements", "left", "right",
                                                "residual_stress", "stretching"});
    if (auto v = f.quantity("length", Dimension::length, true)) beam.length = *v;
    if (auto v = f.quantity("width", Dimension::length, true)) beam.width = *v;
    if (auto v = f.quantity("thickness", Dimension::length, true)) beam.thickness = *v;
    // Out-of-int values are clamped so that check_case reports them as too small or too large.
    if (auto v = f.integer("elements", true)) beam.elements = clamp_to_int(*v);
    if (auto v = f.choice("left", {"clamped", "pinned", "free"}, false)) beam.left = end_condition(*v);
    if (auto v = f.choice("right", {"clamped", "pinned", "free"}, false)) beam.right = end_condition(*v);
    if (auto v = f.quantity("residual_stress", Dimension::pressure, false)) beam.residual_stress = *v;
    if (auto v = f.boolean("stretching", false)) beam.stretching = *v;
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

// A support's adhesion keys: the law, and its parameters only with a law other than "none".
void read_adhesion(FieldReader& f, const std::string& path, Support& s) {
    const auto law = f.choice("adhesion", {"none", "dmt", "jkr"}, false);
    if (law) s.adhesion = *law == "dmt" ? Adhesion::dmt : *law == "jkr" ? Adhesion::jkr : Adhesion::none;
    if (!law && f.has("adhesion")) return;  // the bad value is already reported
    const bool on = s.adhesion != Adhesion::none;
    const std::string condition = path + ".adhesion = \"dmt\" or \"jkr\"";
    // Their values are checked by check_case (a sweep may set them too).
    const auto read = [&](std::string_view key, Dimension d, bool required, double& out) {
        if (!only_with(f, key, on, condition)) return;
        if (auto v = f.quantity(key, d, required)) out = *v;
    };
    read("work_of_adhesion", Dimension::surface_energy, true, s.work_of_adhesion);
    read("contact_radius", Dimension::length, true, s.contact_radius);
    read("adhesion_range", Dimension::length, false, s.adhesion_range);
}

Support read_support(const toml::table& t, const std::string& path, Position at, Reading& r) {
    FieldReader f(t, path, at, r.log,
                  {"position", "side", "gap", "prestress", "stiffness", "damping", "damping_ratio", "adhesion",
                   "work_of_adhesion", "contact_radius", "adhesion_range"});
    Support s;
    if (auto v = f.quantity("position", Dimension::dimensionless, true)) s.position = *v;
    if (auto v = f.choice("side", {"below", "above"}, false)) s.side = (*v == "above") ? Side::above : Side::below;
    f.exclusive("gap", "prestress");
    if (auto v = f.quantity("gap", Dimension::length, false)) {
        s.surface = -*v;
        s.surface_key = "gap";
        if (*v < 0.0) r.value_problems.push_back({path + ".gap", "must not be negative"});
    }
    if (auto v = f.quantity("prestress", Dimension::length, false)) {
        s.surface = *v;
        s.surface_key = "prestress";
        if (*v < 0.0) r.value_problems.push_back({path + ".prestress", "must not be negative"});
    }
    if (auto v = f.quantity("stiffness", Dimension::stiffness, true)) s.stiffness = *v;
    f.exclusive("damping", "damping_ratio");
    if (auto v = f.quantity("damping", Dimension::damping, false)) s.damping = *v;
    if (auto v = f.quantity("damping_ratio", Dimension::dimensionless, false)) s.damping_ratio = *v;
    read_adhesion(f, path, s);
    f.finish();
    return s;
}

// Every entry of an array of tables ([[name]]), each read by read(table, "name[i]", position).
template <class T, class Read>
void read_entries(const toml::array& a, Position at, Reading& r, const std::string& name, std::vector<T>& out,
                  Read read) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        const toml::node& entry = *a.get(i);
        const std::string path = name + "[" + std::to_string(i) + "]";
        const Position p = tomlio::position_of(entry.source(), at);
        const toml::table* t = entry.as_table();
        if (t == nullptr) {
            r.log.problem(p, path, "expected a table (a [[" + name + "]] entry), got " + tomlio::type_name(entry));
            continue;
        }
        out.push_back(read(*t, path, p));
    }
}

// [initial]: the static step before release. Keys of another kind (or velocity shape) are errors;
// they are checked only once the kind itself could be read.
void read_initial(const toml::table& t, Position at, Reading& r, InitialState& s) {
    FieldReader f(t, "initial", at, r.log,
                  {"kind", "position", "displacement", "force", "velocity", "velocity_shape", "velocity_mode"});
    using Kind = InitialState::Kind;
    const auto kind = f.choice("kind", {"rest", "displacement", "force"}, false);
    if (kind) s.kind = *kind == "rest" ? Kind::rest : *kind == "force" ? Kind::force : Kind::displacement;
    if (auto v = f.quantity("position", Dimension::dimensionless, false)) s.position = *v;
    if (kind || !f.has("kind")) {
        if (only_with(f, "displacement", s.kind == Kind::displacement, "initial.kind = \"displacement\"")) {
            if (auto v = f.quantity("displacement", Dimension::length, true)) s.displacement = *v;
        }
        if (only_with(f, "force", s.kind == Kind::force, "initial.kind = \"force\"")) {
            if (auto v = f.quantity("force", Dimension::force, true)) s.force = *v;
        }
    }
    using Velocity = InitialState::Velocity;
    const auto shape = f.choice("velocity_shape", {"none", "uniform", "mode"}, false);
    if (shape || !f.has("velocity_shape")) {
        if (shape) {
            s.velocity_kind = *shape == "mode" ? Velocity::mode : *shape == "uniform" ? Velocity::uniform : Velocity::none;
        } else {
            s.velocity_kind = f.has("velocity") ? Velocity::uniform : Velocity::none;
        }
        const bool moving = s.velocity_kind != Velocity::none;
        if (only_with(f, "velocity", moving, "initial.velocity_shape = \"uniform\" or \"mode\"")) {
            if (auto v = f.quantity("velocity", Dimension::velocity, true)) s.velocity = *v;
        }
        if (only_with(f, "velocity_mode", s.velocity_kind == Velocity::mode, "initial.velocity_shape = \"mode\"")) {
            if (auto v = f.integer("velocity_mode", false)) s.velocity_mode = clamp_to_int(*v);
        }
    }
    f.finish();
}

// One [[loads]] entry; the keys of its time function depend on its kind.
PointLoad read_load(const toml::table& t, const std::string& path, Position at, std::size_t index, Reading& r) {
    FieldReader f(t, path, at, r.log,
                  {"position", "amplitude", "kind", "t_on", "frequency", "phase", "offset", "table"});
    PointLoad p;
    if (auto v = f.quantity("position", Dimension::dimensionless, true)) p.position = *v;
    if (auto v = f.quantity("amplitude", Dimension::force, true)) p.amplitude = *v;
    using Kind = TimeFunction::Kind;
    if (const auto kind = f.choice("kind", {"constant", "step", "harmonic", "table"}, true)) {
        TimeFunction& g = p.time;
        g.kind = *kind == "step" ? Kind::step : *kind == "harmonic" ? Kind::harmonic
                 : *kind == "table" ? Kind::table : Kind::constant;
        const auto only = [&](std::string_view key, Kind k, const char* name) {
            return only_with(f, key, g.kind == k, path + ".kind = \"" + name + "\"");
        };
        if (only("t_on", Kind::step, "step")) {
            if (auto v = f.quantity("t_on", Dimension::time, true)) g.t_on = *v;
        }
        if (only("frequency", Kind::harmonic, "harmonic")) {
            if (auto v = f.quantity("frequency", Dimension::frequency, true)) g.frequency_hz = *v;
        }
        if (only("phase", Kind::harmonic, "harmonic")) {
            if (auto v = f.quantity("phase", Dimension::dimensionless, false)) g.phase = *v;
        }
        if (only("offset", Kind::harmonic, "harmonic")) {
            if (auto v = f.quantity("offset", Dimension::dimensionless, false)) g.offset = *v;
        }
        if (only("table", Kind::table, "table")) {
            if (auto v = f.string("table", true)) {
                if (v->empty()) {
                    f.reject("table", "must not be empty (a CSV file name)");
                } else {
                    r.tables.push_back({index, *v});
                }
            }
        }
    }
    f.finish();
    return p;
}

void read_solver(const toml::table& t, Position at, Reading& r, SolverSettings& s) {
    FieldReader f(t, "solver", at, r.log,
                  {"method", "horizon", "output_step", "group_gap", "grouping", "settle_tolerance", "settle_rule",
                   "settle_velocity", "rtol", "min_search_step", "max_events", "max_steps", "max_static_iterations",
                   "reduced_modes", "fallback"});
    if (auto v = f.choice("method", {"auto", "exact", "cvode"}, false)) {
        s.method = *v == "cvode"   ? SolverSettings::Method::cvode
                   : *v == "exact" ? SolverSettings::Method::exact
                                   : SolverSettings::Method::automatic;
    }
    // In the Case, 0 stands for "not given"; written in the file, these two must be positive.
    const auto positive_time = [&](std::string_view key, double& out) {
        if (auto v = f.quantity(key, Dimension::time, false)) {
            out = *v;
            if (!(*v > 0.0)) r.value_problems.push_back({"solver." + std::string(key), "must be positive"});
        }
    };
    positive_time("horizon", s.horizon);
    positive_time("output_step", s.output_step);
    if (auto v = f.quantity("group_gap", Dimension::time, false)) s.group_gap = *v;
    if (auto v = f.quantity("settle_tolerance", Dimension::dimensionless, false)) s.settle_tolerance = *v;
    if (auto v = f.choice("grouping", {"flights", "none"}, false)) {
        s.grouping = *v == "none" ? SolverSettings::Grouping::none : SolverSettings::Grouping::flights;
        if (s.grouping == SolverSettings::Grouping::none && f.has("group_gap")) {
            f.reject("group_gap", "only with solver.grouping = \"flights\" (with \"none\" no episodes are joined)");
        }
    }
    if (auto v = f.choice("settle_rule", {"penetration", "velocity"}, false)) {
        s.settle_rule = *v == "velocity" ? SolverSettings::SettleRule::velocity : SolverSettings::SettleRule::penetration;
    }
    const bool by_velocity = s.settle_rule == SolverSettings::SettleRule::velocity;
    if (auto v = f.quantity("settle_velocity", Dimension::velocity, by_velocity)) {
        s.settle_velocity = *v;
        if (!by_velocity) f.reject("settle_velocity", "only with solver.settle_rule = \"velocity\"");
        else if (!(*v > 0.0)) r.value_problems.push_back({"solver.settle_velocity", "must be positive"});
    }
    if (by_velocity && f.has("settle_tolerance")) {
        f.reject("settle_tolerance", "only with solver.settle_rule = \"penetration\" (the velocity rule uses settle_velocity)");
    }
    if (auto v = f.quantity("rtol", Dimension::dimensionless, false)) s.rtol = *v;
    if (auto v = f.quantity("min_search_step", Dimension::dimensionless, false)) s.min_search_step = *v;
    if (auto v = f.integer("max_events", false)) s.max_events = static_cast<long>(*v);
    if (auto v = f.integer("max_steps", false)) s.max_steps = static_cast<long>(*v);
    if (auto v = f.integer("max_static_iterations", false)) s.max_static_iterations = static_cast<int>(std::clamp<long long>(*v, -1, 1000000000));
    if (auto v = f.choice("fallback", {"cvode", "none"}, false)) {
        s.fallback = *v == "none" ? SolverSettings::Fallback::none : SolverSettings::Fallback::cvode;
    }
    if (auto v = f.integer("reduced_modes", false)) s.reduced_modes = static_cast<int>(std::clamp<long long>(*v, -1, 1000000000));
    f.finish();
}

Case read_root(const toml::table& root, const std::string& default_name, Reading& r) {
    FieldReader f(root, "", Position{}, r.log,
                  {"name", "beam", "material", "damping", "supports", "initial", "loads", "electrodes", "air", "films",
                   "solver"});
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
        read_entries(*a, f.key_position("supports"), r, "supports", c.supports,
                     [&](const toml::table& t, const std::string& path, Position p) { return read_support(t, path, p, r); });
    }
    // Without [initial] the transient starts from the static equilibrium at rest.
    c.initial.kind = InitialState::Kind::rest;
    if (const auto* t = sub_table(f, "initial", false, at)) {
        c.initial = InitialState{};
        read_initial(*t, at, r, c.initial);
    }
    if (const auto* a = f.array("loads", false, "an array of tables ([[loads]])")) {
        read_entries(*a, f.key_position("loads"), r, "loads", c.loads,
                     [&](const toml::table& t, const std::string& path, Position p) {
                         return read_load(t, path, p, c.loads.size(), r);
                     });
    }
    if (const auto* a = f.array("electrodes", false, "an array of tables ([[electrodes]])")) {
        read_entries(*a, f.key_position("electrodes"), r, "electrodes", c.electrodes,
                     [&](const toml::table& t, const std::string& path, Position p) {
                         std::optional<std::string> table;
                         Electrode e = read_electrode(t, path, p, r.log, r.value_problems, table);
                         if (table) r.tables.push_back({c.electrodes.size(), *table, true});
                         return e;
                     });
    }
    if (const auto* t = sub_table(f, "air", false, at)) c.air = read_air(*t, at, r.log);
    if (const auto* a = f.array("films", false, "an array of tables ([[films]])")) {
        read_entries(*a, f.key_position("films"), r, "films", c.films,
                     [&](const toml::table& t, const std::string& path, Position p) { return read_film(t, path, p, r.log); });
    }
    if (const auto* t = sub_table(f, "solver", false, at)) read_solver(*t, at, r, c.solver);
    f.finish();
    return c;
}

// Escapes line breaks so that every message is one line, whatever the file name or text holds.
[[noreturn]] void throw_problem(const std::string& source, const tomlio::SourceProblem& p) {
    throw InputError(one_line(source + ":" + std::to_string(p.at.line) + ": " + p.key + ": " + p.message));
}

std::string default_name(const std::string& source_name) {
    std::string stem = std::filesystem::path(source_name).stem().string();
    return stem.empty() ? "case" : stem;
}

void read_load_tables(const std::string& source_name, Reading& r, Case& c) {
    const std::filesystem::path folder = std::filesystem::path(source_name).parent_path();
    for (const TableFile& t : r.tables) {
        const std::string file = (folder / t.file).string();
        const std::string key = (t.electrode ? "electrodes[" : "loads[") + std::to_string(t.load) + "].table";
        std::string reason;
        const auto text = file_text(file, reason);
        if (!text) throw_problem(source_name, {r.log.where(key), key, "cannot read " + vi::in_quotes(file) + " (" + reason + ")"});
        if (t.electrode) {
            parse_time_table(*text, file, "V_V", c.electrodes[t.load].time);
        } else {
            parse_load_table(*text, file, c.loads[t.load].time);
        }
    }
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
    read_load_tables(source_name, r, c);

    std::vector<CaseProblem> problems = r.value_problems;
    for (CaseProblem& p : check_case(c)) problems.push_back(std::move(p));
    ReadLog placed;
    for (const CaseProblem& p : problems) placed.problem(r.log.where(p.key), p.key, p.message);
    if (auto p = placed.first()) throw_problem(source_name, *p);
    c.origin.file = source_name;
    c.origin.key_lines = r.log.lines();
    return c;
}

InputError locate_in_case(const Case& c, const InputError& e) {
    const std::string what = e.what();
    const auto colon = what.find(": ");
    if (c.origin.file.empty() || colon == std::string::npos) return e;
    // The key, or failing that its nearest parent ("supports[1].gap" -> "supports[1]" -> "supports").
    std::string key = what.substr(0, colon);
    if (key.find(' ') != std::string::npos) return e;
    int line = 0;
    for (std::string k = key; !k.empty();) {
        const auto it = c.origin.key_lines.find(k);
        if (it != c.origin.key_lines.end()) {
            line = it->second;
            break;
        }
        const auto cut = k.find_last_of(".[");
        k = cut == std::string::npos ? std::string() : k.substr(0, cut);
    }
    return InputError(c.origin.file + ":" + std::to_string(line > 0 ? line : 1) + ": " + what);
}

Case read_case_file(const std::string& path) {
    std::string reason;
    const auto text = file_text(path, reason);
    if (!text) throw InputError(one_line(path + ": cannot read file (" + reason + ")"));
    return read_case_text(*text, path);
}

}  // namespace vi
