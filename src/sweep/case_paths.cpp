#include "sweep/case_paths.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>

#include "io/csv_names.hpp"
#include "io/spelling.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

using Kind = InitialState::Kind;
using Velocity = InitialState::Velocity;
using FunctionKind = TimeFunction::Kind;

// One settable number of a Case. i is the section index (supports[i], loads[i]), k the field index
// (damping.ratios[k]); both 0 where there is none.
struct FieldSpec {
    const char* section;
    const char* field;
    const char* unit;
    bool integer;
    bool indexed;  // field[k] with k in {0, 1}
    double (*get)(const Case& c, std::size_t i, std::size_t k);
    void (*set)(Case& c, std::size_t i, std::size_t k, double v);
    // Why the key means nothing for this case; nullptr when it does.
    const char* (*unused)(const Case& c, std::size_t i);
};

const char* always(const Case&, std::size_t) { return nullptr; }

const char* needs_grouping(const Case& c, std::size_t) {
    return c.solver.grouping == SolverSettings::Grouping::flights ? nullptr : "the case sets solver.grouping = \"none\"";
}
const char* needs_penetration_rule(const Case& c, std::size_t) {
    return c.solver.settle_rule == SolverSettings::SettleRule::penetration ? nullptr
                                                                           : "the case sets solver.settle_rule = \"velocity\"";
}
const char* needs_velocity_rule(const Case& c, std::size_t) {
    return c.solver.settle_rule == SolverSettings::SettleRule::velocity ? nullptr
                                                                        : "only with solver.settle_rule = \"velocity\"";
}
const char* needs_ratios(const Case& c, std::size_t) {
    return c.damping.from_ratios ? nullptr : "the case gives no damping.ratios (add them to the case file to sweep them)";
}
const char* needs_alpha_beta(const Case& c, std::size_t) {
    return c.damping.from_ratios ? "the case gives damping.ratios; sweep damping.ratios[0] or damping.ratios[1]" : nullptr;
}
const char* needs_displacement(const Case& c, std::size_t) {
    return c.initial.kind == Kind::displacement ? nullptr : "only with initial.kind = \"displacement\"";
}
const char* needs_force(const Case& c, std::size_t) {
    return c.initial.kind == Kind::force ? nullptr : "only with initial.kind = \"force\"";
}
const char* needs_velocity(const Case& c, std::size_t) {
    return c.initial.velocity_kind != Velocity::none ? nullptr
                                                     : "only with an initial velocity (initial.velocity_shape not \"none\")";
}
const char* needs_velocity_mode(const Case& c, std::size_t) {
    return c.initial.velocity_kind == Velocity::mode ? nullptr : "only with initial.velocity_shape = \"mode\"";
}
const char* needs_step(const Case& c, std::size_t i) {
    return c.loads[i].time.kind == FunctionKind::step ? nullptr : "only for a load of kind \"step\"";
}
const char* needs_harmonic(const Case& c, std::size_t i) {
    return c.loads[i].time.kind == FunctionKind::harmonic ? nullptr : "only for a load of kind \"harmonic\"";
}

const char* needs_adhesion(const Case& c, std::size_t i) {
    return c.supports[i].adhesion != Adhesion::none ? nullptr
                                                     : "only for a support with adhesion (give its adhesion = \"dmt\" or \"jkr\")";
}

using WaveKind = Waveform::Kind;

const char* needs_not_table(const Case& c, std::size_t i) {
    return c.electrodes[i].waveform.kind == WaveKind::table ? "not for a table waveform (it gives volts itself)" : nullptr;
}
// A shape key of the waveforms `kinds`; `message` says which when the electrode has another.
template <WaveKind... kinds>
const char* needs_waveform(const Case& c, std::size_t i, const char* message) {
    const WaveKind k = c.electrodes[i].waveform.kind;
    return ((k == kinds) || ...) ? nullptr : message;
}
const char* needs_timed(const Case& c, std::size_t i) {
    return needs_waveform<WaveKind::step, WaveKind::ramp, WaveKind::pulse, WaveKind::two_step>(
        c, i, "only for waveform = \"step\", \"ramp\", \"pulse\" or \"two_step\"");
}
const char* needs_edges(const Case& c, std::size_t i) {
    return needs_waveform<WaveKind::ramp, WaveKind::pulse, WaveKind::two_step>(
        c, i, "only for waveform = \"ramp\", \"pulse\" or \"two_step\"");
}
const char* needs_hold(const Case& c, std::size_t i) {
    return needs_waveform<WaveKind::pulse, WaveKind::two_step>(c, i, "only for waveform = \"pulse\" or \"two_step\"");
}
const char* needs_pulse(const Case& c, std::size_t i) {
    return needs_waveform<WaveKind::pulse>(c, i, "only for waveform = \"pulse\"");
}
const char* needs_two_step(const Case& c, std::size_t i) {
    return needs_waveform<WaveKind::two_step>(c, i, "only for waveform = \"two_step\"");
}
const char* needs_electrode_sine(const Case& c, std::size_t i) {
    return needs_waveform<WaveKind::sine>(c, i, "only for waveform = \"sine\"");
}

// Sets a value of electrode i's waveform (or its voltage) and builds its g(t) again.
template <class Set>
void set_waveform(Case& c, std::size_t i, Set set) {
    Electrode& e = c.electrodes[i];
    set(e);
    if (built_from_shape(e.waveform.kind)) e.time = waveform_function(e.waveform, e.voltage);
}
const char* needs_dielectric(const Case& c, std::size_t i) {
    return c.electrodes[i].dielectric_thickness > 0.0 ? nullptr : "only with a dielectric_thickness above 0";
}

const char* needs_air(const Case& c, std::size_t) { return c.air ? nullptr : "only with an [air] table"; }

// The number as an int; the caller has checked that it is whole and in range.
int whole(double v) { return static_cast<int>(v); }

void set_surface(Support& s, const char* key, double surface) {
    s.surface = surface;
    s.surface_key = key;
}

#define VI_GET(expr) [](const Case& c, std::size_t i, std::size_t k) -> double { (void)i; (void)k; return (expr); }
#define VI_SET(stmt) [](Case& c, std::size_t i, std::size_t k, double v) { (void)i; (void)k; stmt; }

const FieldSpec kFields[] = {
    {"beam", "length", "m", false, false, VI_GET(c.beam.length), VI_SET(c.beam.length = v), always},
    {"beam", "width", "m", false, false, VI_GET(c.beam.width), VI_SET(c.beam.width = v), always},
    {"beam", "thickness", "m", false, false, VI_GET(c.beam.thickness), VI_SET(c.beam.thickness = v), always},
    {"beam", "elements", "-", true, false, VI_GET(c.beam.elements), VI_SET(c.beam.elements = whole(v)), always},
    {"beam", "residual_stress", "Pa", false, false, VI_GET(c.beam.residual_stress),
     VI_SET(c.beam.residual_stress = v), always},
    {"material", "youngs_modulus", "Pa", false, false, VI_GET(c.material.youngs_modulus),
     VI_SET(c.material.youngs_modulus = v), always},
    {"material", "density", "kg/m^3", false, false, VI_GET(c.material.density), VI_SET(c.material.density = v), always},
    {"material", "poisson_ratio", "-", false, false, VI_GET(c.material.poisson_ratio),
     VI_SET(c.material.poisson_ratio = v), always},
    {"supports", "position", "x/l", false, false, VI_GET(c.supports[i].position), VI_SET(c.supports[i].position = v),
     always},
    {"supports", "gap", "m", false, false, VI_GET(-c.supports[i].surface),
     VI_SET(set_surface(c.supports[i], "gap", -v)), always},
    {"supports", "prestress", "m", false, false, VI_GET(c.supports[i].surface),
     VI_SET(set_surface(c.supports[i], "prestress", v)), always},
    {"supports", "stiffness", "N/m", false, false, VI_GET(c.supports[i].stiffness),
     VI_SET(c.supports[i].stiffness = v), always},
    {"supports", "damping", "N s/m", false, false, VI_GET(c.supports[i].damping),
     VI_SET(c.supports[i].damping = v; c.supports[i].damping_ratio.reset()), always},
    {"supports", "damping_ratio", "-", false, false, VI_GET(c.supports[i].damping_ratio.value_or(0.0)),
     VI_SET(c.supports[i].damping_ratio = v; c.supports[i].damping = 0.0), always},
    {"supports", "work_of_adhesion", "J/m^2", false, false, VI_GET(c.supports[i].work_of_adhesion),
     VI_SET(c.supports[i].work_of_adhesion = v), needs_adhesion},
    {"supports", "contact_radius", "m", false, false, VI_GET(c.supports[i].contact_radius),
     VI_SET(c.supports[i].contact_radius = v), needs_adhesion},
    {"supports", "adhesion_range", "m", false, false, VI_GET(c.supports[i].adhesion_range),
     VI_SET(c.supports[i].adhesion_range = v), needs_adhesion},
    {"damping", "alpha", "1/s", false, false, VI_GET(c.damping.alpha), VI_SET(c.damping.alpha = v), needs_alpha_beta},
    {"damping", "beta", "s", false, false, VI_GET(c.damping.beta), VI_SET(c.damping.beta = v), needs_alpha_beta},
    {"damping", "ratios", "-", false, true, VI_GET(k == 0 ? c.damping.ratio1 : c.damping.ratio2),
     VI_SET((k == 0 ? c.damping.ratio1 : c.damping.ratio2) = v), needs_ratios},
    {"damping", "modes", "-", true, true, VI_GET(k == 0 ? c.damping.mode1 : c.damping.mode2),
     VI_SET((k == 0 ? c.damping.mode1 : c.damping.mode2) = whole(v)), needs_ratios},
    {"initial", "position", "x/l", false, false, VI_GET(c.initial.position), VI_SET(c.initial.position = v), always},
    {"initial", "displacement", "m", false, false, VI_GET(c.initial.displacement),
     VI_SET(c.initial.displacement = v), needs_displacement},
    {"initial", "force", "N", false, false, VI_GET(c.initial.force), VI_SET(c.initial.force = v), needs_force},
    {"initial", "velocity", "m/s", false, false, VI_GET(c.initial.velocity), VI_SET(c.initial.velocity = v),
     needs_velocity},
    {"initial", "velocity_mode", "-", true, false, VI_GET(c.initial.velocity_mode),
     VI_SET(c.initial.velocity_mode = whole(v)), needs_velocity_mode},
    {"loads", "position", "x/l", false, false, VI_GET(c.loads[i].position), VI_SET(c.loads[i].position = v), always},
    {"loads", "amplitude", "N", false, false, VI_GET(c.loads[i].amplitude), VI_SET(c.loads[i].amplitude = v), always},
    {"loads", "t_on", "s", false, false, VI_GET(c.loads[i].time.t_on), VI_SET(c.loads[i].time.t_on = v), needs_step},
    {"loads", "frequency", "Hz", false, false, VI_GET(c.loads[i].time.frequency_hz),
     VI_SET(c.loads[i].time.frequency_hz = v), needs_harmonic},
    {"loads", "phase", "rad", false, false, VI_GET(c.loads[i].time.phase), VI_SET(c.loads[i].time.phase = v),
     needs_harmonic},
    {"loads", "offset", "-", false, false, VI_GET(c.loads[i].time.offset), VI_SET(c.loads[i].time.offset = v),
     needs_harmonic},
    {"electrodes", "from", "x/l", false, false, VI_GET(c.electrodes[i].from), VI_SET(c.electrodes[i].from = v), always},
    {"electrodes", "to", "x/l", false, false, VI_GET(c.electrodes[i].to), VI_SET(c.electrodes[i].to = v), always},
    {"electrodes", "gap", "m", false, false, VI_GET(c.electrodes[i].gap), VI_SET(c.electrodes[i].gap = v), always},
    {"electrodes", "dielectric_thickness", "m", false, false, VI_GET(c.electrodes[i].dielectric_thickness),
     VI_SET(c.electrodes[i].dielectric_thickness = v), always},
    {"electrodes", "dielectric_permittivity", "-", false, false, VI_GET(c.electrodes[i].dielectric_permittivity),
     VI_SET(c.electrodes[i].dielectric_permittivity = v), needs_dielectric},
    {"electrodes", "voltage", "V", false, false, VI_GET(c.electrodes[i].voltage),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.voltage = v; })), needs_not_table},
    {"electrodes", "t_on", "s", false, false, VI_GET(c.electrodes[i].waveform.t_on),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.waveform.t_on = v; })), needs_timed},
    {"electrodes", "rise", "s", false, false, VI_GET(c.electrodes[i].waveform.rise),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.waveform.rise = v; })), needs_edges},
    {"electrodes", "hold", "s", false, false, VI_GET(c.electrodes[i].waveform.hold),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.waveform.hold = v; })), needs_hold},
    {"electrodes", "fall", "s", false, false, VI_GET(c.electrodes[i].waveform.fall),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.waveform.fall = v; })), needs_pulse},
    {"electrodes", "level", "-", false, false, VI_GET(c.electrodes[i].waveform.level),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.waveform.level = v; })), needs_two_step},
    {"electrodes", "frequency", "Hz", false, false, VI_GET(c.electrodes[i].waveform.frequency),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.waveform.frequency = v; })), needs_electrode_sine},
    {"electrodes", "phase", "rad", false, false, VI_GET(c.electrodes[i].waveform.phase),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.waveform.phase = v; })), needs_electrode_sine},
    {"electrodes", "bias", "V", false, false, VI_GET(c.electrodes[i].waveform.bias),
     VI_SET(set_waveform(c, i, [v](Electrode& e) { e.waveform.bias = v; })), needs_electrode_sine},
    {"air", "pressure", "Pa", false, false, VI_GET(c.air ? c.air->pressure : 0.0), VI_SET(c.air->pressure = v), needs_air},
    {"air", "temperature", "K", false, false, VI_GET(c.air ? c.air->temperature : 0.0), VI_SET(c.air->temperature = v),
     needs_air},
    {"air", "viscosity", "Pa s", false, false, VI_GET(c.air ? c.air->viscosity : 0.0), VI_SET(c.air->viscosity = v),
     needs_air},
    {"air", "mean_free_path", "m", false, false, VI_GET(c.air ? c.air->lambda() : 0.0),
     VI_SET(c.air->mean_free_path = v), needs_air},
    {"solver", "horizon", "s", false, false, VI_GET(c.solver.horizon), VI_SET(c.solver.horizon = v), always},
    {"solver", "output_step", "s", false, false, VI_GET(c.solver.output_step), VI_SET(c.solver.output_step = v), always},
    {"solver", "group_gap", "s", false, false, VI_GET(c.solver.group_gap), VI_SET(c.solver.group_gap = v), needs_grouping},
    {"solver", "settle_tolerance", "-", false, false, VI_GET(c.solver.settle_tolerance),
     VI_SET(c.solver.settle_tolerance = v), needs_penetration_rule},
    {"solver", "settle_velocity", "m/s", false, false, VI_GET(c.solver.settle_velocity),
     VI_SET(c.solver.settle_velocity = v), needs_velocity_rule},
    {"solver", "rtol", "-", false, false, VI_GET(c.solver.rtol), VI_SET(c.solver.rtol = v), always},
    {"solver", "min_search_step", "periods", false, false, VI_GET(c.solver.min_search_step),
     VI_SET(c.solver.min_search_step = v), always},
    {"solver", "max_events", "-", true, false, VI_GET(static_cast<double>(c.solver.max_events)),
     VI_SET(c.solver.max_events = static_cast<long>(v)), always},
    {"solver", "max_steps", "-", true, false, VI_GET(static_cast<double>(c.solver.max_steps)),
     VI_SET(c.solver.max_steps = static_cast<long>(v)), always},
    {"solver", "max_static_iterations", "-", true, false, VI_GET(static_cast<double>(c.solver.max_static_iterations)),
     VI_SET(c.solver.max_static_iterations = static_cast<int>(v)), always},
    {"solver", "reduced_modes", "-", true, false, VI_GET(static_cast<double>(c.solver.reduced_modes)),
     VI_SET(c.solver.reduced_modes = static_cast<int>(v)), always},
};

#undef VI_GET
#undef VI_SET

bool indexed_section(std::string_view s) { return s == "supports" || s == "loads" || s == "electrodes"; }

std::size_t section_length(const Case& c, std::string_view s) {
    return s == "supports" ? c.supports.size() : s == "electrodes" ? c.electrodes.size() : c.loads.size();
}

const FieldSpec* find_field(const CasePath& p) {
    for (const FieldSpec& f : kFields) {
        if (p.section == f.section && p.field == f.field) return &f;
    }
    return nullptr;
}

const FieldSpec& field_of(const CasePath& p) {
    const FieldSpec* f = find_field(p);
    if (!f) throw InputError(p.text() + ": unknown key");
    return *f;
}

std::string section_form(std::string_view s) { return std::string(s) + (indexed_section(s) ? "[i]" : ""); }

std::string known_sections() {
    std::string out;
    for (const FieldSpec& f : kFields) {
        const std::string form = section_form(f.section);
        if (out.find(form) == std::string::npos) out += (out.empty() ? "" : ", ") + form;
    }
    return out;
}

std::string known_fields(std::string_view section) {
    std::string out;
    for (const FieldSpec& f : kFields) {
        if (section == f.section) out += (out.empty() ? "" : ", ") + std::string(f.field) + (f.indexed ? "[k]" : "");
    }
    return out;
}

// " (did you mean 'x'?)" when name is a near misspelling of a section (field empty: sections) or of
// a field of section; else " (accepted: ...)".
std::string spelling_hint(std::string_view name, std::string_view section) {
    std::vector<std::string_view> names;
    for (const FieldSpec& f : kFields) names.push_back(section.empty() ? f.section : f.field);
    std::vector<std::string_view> candidates;
    for (std::size_t k = 0; k < names.size(); ++k) {
        const bool ours = section.empty() || kFields[k].section == section;
        if (ours && std::find(candidates.begin(), candidates.end(), names[k]) == candidates.end()) candidates.push_back(names[k]);
    }
    if (const auto guess = closest_spelling(name, candidates)) return " (did you mean '" + *guess + "'?)";
    return " (accepted: " + (section.empty() ? known_sections() : known_fields(section)) + ")";
}

// Reads "name" or "name[digits]" from the front of s.
struct Part {
    std::string name;
    std::optional<std::size_t> index;
};

Part read_part(std::string_view& s, std::string_view whole_text) {
    Part part;
    std::size_t n = 0;
    while (n < s.size() && (std::islower(static_cast<unsigned char>(s[n])) || s[n] == '_')) ++n;
    part.name = std::string(s.substr(0, n));
    s.remove_prefix(n);
    if (part.name.empty()) {
        throw InputError("\"" + std::string(whole_text) + "\" is not a path like supports[0].position or beam.length");
    }
    if (!s.empty() && s.front() == '[') {
        const std::size_t close = s.find(']');
        const std::string_view digits = s.substr(1, close == std::string_view::npos ? 0 : close - 1);
        if (close == std::string_view::npos || digits.empty() || digits.size() > 9 ||
            digits.find_first_not_of("0123456789") != std::string_view::npos) {
            throw InputError(part.name + ": expected an index in brackets, like " + part.name + "[0]");
        }
        part.index = std::stoul(std::string(digits));
        s.remove_prefix(close + 1);
    }
    return part;
}

std::string plural(std::size_t n, const std::string& word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

std::string CasePath::text() const {
    std::string t = section;
    const auto add_index = [&t](std::size_t i) {
        t += '[';
        t += std::to_string(i);
        t += ']';
    };
    if (section_index) add_index(*section_index);
    t += '.';
    t += field;
    if (field_index) add_index(*field_index);
    return t;
}

CasePath resolve_case_path(std::string_view text, const Case& c) {
    std::string_view rest = text;
    CasePath p;
    const Part section = read_part(rest, text);
    p.section = section.name;
    p.section_index = section.index;
    if (known_fields(p.section).empty()) {
        throw InputError("unknown key '" + p.section + "'" + spelling_hint(p.section, ""));
    }
    if (rest.empty() || rest.front() != '.') {
        if (rest.empty() && !p.section_index && indexed_section(p.section)) {
            throw InputError(p.section + ": needs an index and a key, like " + p.section + "[0].position");
        }
        if (rest.empty()) throw InputError(section_form(p.section) + ": needs a key (" + known_fields(p.section) + ")");
        throw InputError("\"" + std::string(text) + "\" is not a path like supports[0].position or beam.length");
    }
    rest.remove_prefix(1);
    const Part field = read_part(rest, text);
    p.field = field.name;
    p.field_index = field.index;
    if (!rest.empty()) throw InputError("\"" + std::string(text) + "\" is not a path like supports[0].position or beam.length");

    const std::string where = section_form(p.section);
    if (!indexed_section(p.section) && p.section_index) throw InputError(p.section + ": takes no index");
    const FieldSpec* f = find_field(p);
    if (!f) {
        throw InputError("unknown key '" + p.field + "' in " + where + spelling_hint(p.field, p.section));
    }
    if (indexed_section(p.section)) {
        if (!p.section_index) throw InputError(p.section + ": needs an index, like " + p.section + "[0]." + p.field);
        const std::size_t n = section_length(c, p.section);
        if (*p.section_index >= n) {
            throw InputError(p.section + "[" + std::to_string(*p.section_index) + "]: index out of range (the case has " +
                             plural(n, p.section == "supports" ? "support" : p.section == "electrodes" ? "electrode" : "load") + ")");
        }
    }
    if (f->indexed && !p.field_index) {
        throw InputError(p.section + "." + p.field + ": needs an index, [0] or [1]");
    }
    if (!f->indexed && p.field_index) throw InputError(p.section + "." + p.field + ": takes no index");
    if (f->indexed && *p.field_index > 1) {
        throw InputError(p.text() + ": index out of range (0 or 1)");
    }
    if (const char* why = f->unused(c, p.section_index.value_or(0))) throw InputError(p.text() + ": " + why);
    return p;
}

bool is_integer_path(const CasePath& p) { return field_of(p).integer; }

std::string case_path_unit(const CasePath& p) { return field_of(p).unit; }

std::string case_path_column(const CasePath& p) { return p.text() + csv_unit_suffix(case_path_unit(p)); }

std::optional<Dimension> case_path_dimension(const CasePath& p) {
    static constexpr std::pair<std::string_view, Dimension> kBySi[] = {
        {"m", Dimension::length},         {"Pa", Dimension::pressure},       {"kg/m^3", Dimension::density},
        {"N/m", Dimension::stiffness},    {"N s/m", Dimension::damping},     {"N", Dimension::force},
        {"s", Dimension::time},           {"m/s", Dimension::velocity},      {"Hz", Dimension::frequency},
        {"1/s", Dimension::mass_damping}, {"V", Dimension::voltage},         {"J/m^2", Dimension::surface_energy},
        {"Pa s", Dimension::viscosity},   {"K", Dimension::temperature}};
    const std::string_view unit = field_of(p).unit;
    for (const auto& [si, d] : kBySi)
        if (si == unit) return d;
    return std::nullopt;
}

double get_case_value(const Case& c, const CasePath& p) {
    return field_of(p).get(c, p.section_index.value_or(0), p.field_index.value_or(0));
}

void set_case_value(Case& c, const CasePath& p, double value) {
    const FieldSpec& f = field_of(p);
    if (f.integer && !(value == std::floor(value) && std::abs(value) <= INT_MAX)) {
        throw InputError(p.text() + ": must be a whole number");
    }
    if ((p.field == "gap" || p.field == "prestress") && value < 0.0) {
        throw InputError(p.text() + ": must not be negative");
    }
    f.set(c, p.section_index.value_or(0), p.field_index.value_or(0), value);
}

std::vector<std::string> case_path_forms() {
    std::vector<std::string> out;
    for (const FieldSpec& f : kFields) out.push_back(section_form(f.section) + "." + f.field + (f.indexed ? "[k]" : ""));
    return out;
}

std::vector<std::pair<std::string, std::string>> case_path_form_units() {
    std::vector<std::pair<std::string, std::string>> out;
    const std::vector<std::string> forms = case_path_forms();
    for (std::size_t k = 0; k < forms.size(); ++k) out.emplace_back(forms[k], kFields[k].unit);
    return out;
}

}  // namespace vi
