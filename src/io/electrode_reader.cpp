#include "io/electrode_reader.hpp"

#include <string_view>

namespace vi {

using tomlio::FieldReader;
using tomlio::only_with;

Electrode read_electrode(const toml::table& t, const std::string& path, tomlio::Position at, tomlio::ReadLog& log,
                         std::vector<CaseProblem>& value_problems, std::optional<std::string>& table_file) {
    FieldReader f(t, path, at, log,
                  {"from", "to", "side", "gap", "dielectric_thickness", "dielectric_permittivity", "dielectric_modulus",
                   "work_of_adhesion", "adhesion_range", "width", "fringing", "voltage", "waveform", "t_on", "rise", "hold",
                   "fall", "level", "frequency", "phase", "bias", "table"});
    Electrode e;
    if (auto v = f.quantity("from", Dimension::dimensionless, true)) e.from = *v;
    if (auto v = f.quantity("to", Dimension::dimensionless, true)) e.to = *v;
    if (auto v = f.choice("side", {"below", "above"}, false)) e.side = (*v == "above") ? Side::above : Side::below;
    if (auto v = f.quantity("gap", Dimension::length, true)) e.gap = *v;
    if (auto v = f.quantity("dielectric_thickness", Dimension::length, false)) e.dielectric_thickness = *v;
    if (auto v = f.quantity("dielectric_permittivity", Dimension::dimensionless, false)) e.dielectric_permittivity = *v;
    if (auto v = f.quantity("dielectric_modulus", Dimension::pressure, false)) e.dielectric_modulus = *v;
    if (f.has("dielectric_modulus") && !f.has("dielectric_thickness")) {
        f.reject("dielectric_modulus", "needs dielectric_thickness (the layer it belongs to)");
    }
    if (f.has("dielectric_permittivity") && !f.has("dielectric_thickness")) {
        f.reject("dielectric_permittivity", "needs dielectric_thickness (the layer it belongs to)");
    }
    // The beam's adhesion to the layer (docs/adhesion.md §9); values are checked by check_case.
    if (auto v = f.quantity("work_of_adhesion", Dimension::surface_energy, false)) e.work_of_adhesion = *v;
    if (f.has("work_of_adhesion") && !f.has("dielectric_thickness")) {
        f.reject("work_of_adhesion", "needs dielectric_thickness (the layer the beam adheres to)");
    }
    if (auto v = f.quantity("adhesion_range", Dimension::length, false)) e.adhesion_range = *v;
    if (f.has("adhesion_range") && !f.has("work_of_adhesion")) {
        f.reject("adhesion_range", "needs work_of_adhesion (the adhesion it is the range of)");
    }
    if (auto v = f.quantity("width", Dimension::length, false)) {
        e.width = *v;
        if (!(*v > 0.0)) value_problems.push_back({path + ".width", "must be positive (or left out: the beam's width)"});
    }
    if (auto v = f.choice("fringing", {"none", "meijs-fokkema"}, false)) {
        e.fringing = *v == "none" ? Fringing::none : Fringing::meijs_fokkema;
    }
    const auto kind = f.choice("waveform", {"constant", "step", "ramp", "pulse", "two_step", "sine", "table"}, false);
    const std::string w = kind ? *kind : (f.has("waveform") ? "" : "constant");
    using Kind = Waveform::Kind;
    for (const Kind k : {Kind::constant, Kind::step, Kind::ramp, Kind::pulse, Kind::two_step, Kind::sine, Kind::table}) {
        if (w == waveform_name(k)) e.waveform.kind = k;
    }
    // A table gives volts itself (columns t_s,V_V); every other waveform scales g(t) by `voltage`.
    e.voltage = 1.0;
    if (only_with(f, "voltage", w != "table", path + ".waveform other than \"table\" (a table gives volts)")) {
        if (auto v = f.quantity("voltage", Dimension::voltage, w != "table" && !w.empty())) e.voltage = *v;
    }
    // Which keys belong to which waveform is the reader's to say; their values are check_case's
    // (a sweep or an optimisation may set them too).
    const auto key = [&](std::string_view name, Dimension d, bool allowed, const char* which, bool required,
                         double& out) {
        if (!only_with(f, name, allowed, path + ".waveform = " + which)) return;
        if (auto v = f.quantity(name, d, required)) out = *v;
    };
    Waveform& g = e.waveform;
    const bool timed = w == "step" || w == "ramp" || w == "pulse" || w == "two_step";
    const bool edged = w == "ramp" || w == "pulse" || w == "two_step";
    key("t_on", Dimension::time, timed, "\"step\", \"ramp\", \"pulse\" or \"two_step\"", false, g.t_on);
    key("rise", Dimension::time, edged, "\"ramp\", \"pulse\" or \"two_step\"", true, g.rise);
    key("hold", Dimension::time, w == "pulse" || w == "two_step", "\"pulse\" or \"two_step\"", true, g.hold);
    key("fall", Dimension::time, w == "pulse", "\"pulse\"", true, g.fall);
    key("level", Dimension::dimensionless, w == "two_step", "\"two_step\"", true, g.level);
    const bool sine = w == "sine";
    key("frequency", Dimension::frequency, sine, "\"sine\"", true, g.frequency);
    key("phase", Dimension::dimensionless, sine, "\"sine\"", false, g.phase);
    key("bias", Dimension::voltage, sine, "\"sine\"", false, g.bias);
    if (built_from_shape(g.kind)) e.time = waveform_function(g, e.voltage);
    if (g.kind == Kind::table) e.time.kind = TimeFunction::Kind::table;
    if (only_with(f, "table", w == "table", path + ".waveform = \"table\"")) {
        if (auto v = f.string("table", true)) {
            if (v->empty()) f.reject("table", "must not be empty (a CSV file name with columns t_s,V_V)");
            else table_file = *v;
        }
    }
    f.finish();
    return e;
}

}  // namespace vi
