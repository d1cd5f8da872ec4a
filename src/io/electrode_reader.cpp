#include "io/electrode_reader.hpp"

#include <string_view>

namespace vi {

using tomlio::FieldReader;
using tomlio::only_with;

namespace {

// Ramps and pulses are piecewise linear, so they become tables: every solver already integrates
// those exactly between knots and stops at each knot.
TimeFunction ramp(double t_on, double rise) {
    TimeFunction g;
    g.kind = TimeFunction::Kind::table;
    g.times = {t_on, t_on + rise};
    g.values = {0.0, 1.0};
    return g;
}

TimeFunction pulse(double t_on, double rise, double hold, double fall) {
    TimeFunction g;
    g.kind = TimeFunction::Kind::table;
    g.times = {t_on, t_on + rise, t_on + rise + hold, t_on + rise + hold + fall};
    g.values = {0.0, 1.0, 1.0, 0.0};
    return g;
}

}  // namespace

Electrode read_electrode(const toml::table& t, const std::string& path, tomlio::Position at, tomlio::ReadLog& log,
                         std::vector<CaseProblem>& value_problems, std::optional<std::string>& table_file) {
    FieldReader f(t, path, at, log,
                  {"from", "to", "side", "gap", "dielectric_thickness", "dielectric_permittivity", "dielectric_modulus",
                   "work_of_adhesion", "adhesion_range", "width", "fringing", "voltage", "waveform", "t_on", "rise", "hold", "fall", "frequency", "phase", "bias",
                   "table"});
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
    const auto kind = f.choice("waveform", {"constant", "step", "ramp", "pulse", "sine", "table"}, false);
    const std::string w = kind ? *kind : (f.has("waveform") ? "" : "constant");
    // A table gives volts itself (columns t_s,V_V); every other waveform scales g(t) by `voltage`.
    e.voltage = 1.0;
    if (only_with(f, "voltage", w != "table", path + ".waveform other than \"table\" (a table gives volts)")) {
        if (auto v = f.quantity("voltage", Dimension::voltage, w != "table" && !w.empty())) e.voltage = *v;
    }
    const auto only = [&](std::string_view key, bool allowed, const char* which) {
        return only_with(f, key, allowed, path + ".waveform = " + which);
    };
    const auto time_key = [&](std::string_view key, bool allowed, const char* which, bool required, double fallback) {
        double out = fallback;
        if (only(key, allowed, which)) {
            if (auto v = f.quantity(key, Dimension::time, required)) {
                out = *v;
                if (key != "t_on" && !(*v > 0.0)) value_problems.push_back({path + "." + std::string(key), "must be positive"});
                if (key == "t_on" && *v < 0.0) value_problems.push_back({path + ".t_on", "must not be negative"});
            }
        }
        return out;
    };
    const bool timed = w == "step" || w == "ramp" || w == "pulse";
    const double t_on = time_key("t_on", timed, "\"step\", \"ramp\" or \"pulse\"", false, 0.0);
    const double rise = time_key("rise", w == "ramp" || w == "pulse", "\"ramp\" or \"pulse\"", true, 1.0);
    const double hold = time_key("hold", w == "pulse", "\"pulse\"", true, 1.0);
    const double fall = time_key("fall", w == "pulse", "\"pulse\"", true, 1.0);
    using Kind = TimeFunction::Kind;
    if (w == "step") {
        e.time.kind = Kind::step;
        e.time.t_on = t_on;
    } else if (w == "ramp") {
        e.time = ramp(t_on, rise);
    } else if (w == "pulse") {
        e.time = pulse(t_on, rise, hold, fall);
    } else if (w == "sine") {
        // V = bias + voltage sin(2 pi f t + phase): the harmonic g(t) with offset = bias / voltage.
        e.time.kind = Kind::harmonic;
    } else if (w == "table") {
        e.time.kind = Kind::table;
    }
    const bool sine = w == "sine";
    if (only("frequency", sine, "\"sine\"")) {
        if (auto v = f.quantity("frequency", Dimension::frequency, true)) {
            e.time.frequency_hz = *v;
            if (!(*v > 0.0)) value_problems.push_back({path + ".frequency", "must be positive"});
        }
    }
    if (only("phase", sine, "\"sine\"")) {
        if (auto v = f.quantity("phase", Dimension::dimensionless, false)) e.time.phase = *v;
    }
    if (only("bias", sine, "\"sine\"")) {
        if (auto v = f.quantity("bias", Dimension::voltage, false)) {
            if (e.voltage > 0.0) e.time.offset = *v / e.voltage;
            else value_problems.push_back({path + ".voltage", "must be positive with waveform = \"sine\" (the amplitude)"});
        }
    }
    if (only("table", w == "table", "\"table\"")) {
        if (auto v = f.string("table", true)) {
            if (v->empty()) f.reject("table", "must not be empty (a CSV file name with columns t_s,V_V)");
            else table_file = *v;
        }
    }
    f.finish();
    return e;
}

}  // namespace vi
