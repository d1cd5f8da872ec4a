#include "model/case_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "model/case_schema.hpp"
#include "model/key_checks.hpp"
#include "model/magnitude_checks.hpp"
#include "model/run_estimate.hpp"
#include "model/section_checks.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

std::string support_key(std::size_t i, const char* field) {
    return "supports[" + std::to_string(i) + "]." + field;
}

// The rules for the values of a time function built in code (an electrode's "given" g(t)), whose
// keys no case file gave.
void require_positive(std::vector<CaseProblem>& out, const std::string& key, double value) {
    if (!std::isfinite(value)) {
        out.push_back({key, "must be a finite number"});
    } else if (!(value > 0.0)) {
        out.push_back({key, "must be positive"});
    }
}

void require_non_negative(std::vector<CaseProblem>& out, const std::string& key, double value) {
    if (!std::isfinite(value)) {
        out.push_back({key, "must be a finite number"});
    } else if (value < 0.0) {
        out.push_back({key, "must not be negative"});
    }
}

void require_finite(std::vector<CaseProblem>& out, const std::string& key, double value) {
    if (!std::isfinite(value)) out.push_back({key, "must be a finite number"});
}

// True when x/l = position is the right end and that end is clamped or pinned (v fixed there).
bool at_fixed_end(const Case& c, double position) {
    return position == 1.0 && c.beam.right != EndCondition::free;
}

std::string number_text(double v) { return significant(v == 0.0 ? 0.0 : v, 6); }  // no "-0"

// Height of a support's surface in beam coordinates (v, positive up).
double surface_height(const Support& s) { return s.side == Side::below ? s.surface : -s.surface; }

// An adhesive support needs a solver that takes its law (the exact solver's linear forms have no
// cohesive zone; docs/adhesion.md §3).
void check_adhesion(std::vector<CaseProblem>& out, const Case& c, std::size_t i) {
    const Support& s = c.supports[i];
    if (s.adhesion == Adhesion::none) return;
    if (c.solver.method == SolverSettings::Method::exact) {
        std::string why = "\"exact\" cannot take the adhesive contact of ";
        why.append(support_key(i, "adhesion"))
            .append(" (its cohesive law is not one of the exact solver's linear forms); use \"cvode\" or \"auto\"");
        out.push_back({"solver.method", why});
    }
}

// A support below and one above at the same place must leave room for the beam between them.
void check_opposite_supports(std::vector<CaseProblem>& out, const std::vector<Support>& supports) {
    for (std::size_t i = 0; i < supports.size(); ++i) {
        const Support& s = supports[i];
        for (std::size_t j = 0; j < i; ++j) {
            const Support& o = supports[j];
            if (o.side == s.side || std::abs(o.position - s.position) > 1e-12) continue;
            const double below = surface_height(s.side == Side::below ? s : o);
            const double above = surface_height(s.side == Side::above ? s : o);
            if (below < above) continue;
            const std::string key = !s.surface_key.empty() ? s.surface_key
                                    : s.surface < 0.0     ? "gap"
                                    : s.surface > 0.0     ? "prestress"
                                                          : "position";
            out.push_back({support_key(i, key.c_str()),
                           "overlaps supports[" + std::to_string(j) + "] on the other side (the surface below, at v = " +
                               number_text(below) + " m, must lie under the surface above, at v = " +
                               number_text(above) + " m)"});
        }
    }
}

void check_initial(std::vector<CaseProblem>& out, const Case& c) {
    const InitialState& in = c.initial;
    using Kind = InitialState::Kind;
    using Velocity = InitialState::Velocity;
    const bool steps = (in.kind == Kind::displacement && in.displacement != 0.0) ||
                       (in.kind == Kind::force && in.force != 0.0) ||
                       (in.velocity_kind == Velocity::mode && in.velocity != 0.0);
    if (steps && at_fixed_end(c, in.position)) {
        out.push_back({"initial.position", "lies at a clamped or pinned end, where v cannot move"});
    }
}

// A g(t) given in code or by a table: the keys of the kinds a case file cannot give an electrode, and
// a table's rows, under `at` ("loads[0]." or "electrodes[1].").
void check_time_function(std::vector<CaseProblem>& out, const std::string& at, const TimeFunction& g) {
    switch (g.kind) {
        case TimeFunction::Kind::constant: break;
        case TimeFunction::Kind::step: require_non_negative(out, at + "t_on", g.t_on); break;
        case TimeFunction::Kind::harmonic:
            require_positive(out, at + "frequency", g.frequency_hz);
            require_finite(out, at + "phase", g.phase);
            require_finite(out, at + "offset", g.offset);
            break;
        case TimeFunction::Kind::table: {
            bool ok = !g.times.empty() && g.times.size() == g.values.size();
            for (std::size_t i = 0; ok && i < g.times.size(); ++i) {
                ok = std::isfinite(g.times[i]) && std::isfinite(g.values[i]) && (i == 0 || g.times[i] > g.times[i - 1]);
            }
            if (!ok) out.push_back({at + "table", "needs finite rows with strictly increasing times"});
            break;
        }
    }
}

void check_load(std::vector<CaseProblem>& out, const Case& c, std::size_t k) {
    const PointLoad& p = c.loads[k];
    const std::string at = "loads[" + std::to_string(k) + "].";
    if (at_fixed_end(c, p.position)) out.push_back({at + "position", "a load at a clamped or pinned end does nothing"});
    if (p.time.kind == TimeFunction::Kind::table) check_time_function(out, at, p.time);
}

// Meijs and Fokkema state their formula for 0.3 <= w/g <= 30 and 0.3 <= t/g <= 30; outside it the
// fringing force is an extrapolation nobody has checked, so a case must not rely on it. Checked at
// the electrical gap at rest (as the gap closes w/g grows past the range: docs/electrostatics.md §2).
void check_fringing_range(std::vector<CaseProblem>& out, const Case& c, std::size_t k) {
    const Electrode& e = c.electrodes[k];
    if (e.fringing != Fringing::meijs_fokkema) return;
    const double gap = (e.gap - e.dielectric_thickness) + e.dielectric_thickness / e.dielectric_permittivity;
    // The beam's width and thickness under the electrode's middle (the section its force takes).
    double width = c.beam.width, thickness = c.beam.thickness;
    for (const BeamSection& s : c.beam.sections) {
        if (0.5 * (e.from + e.to) < s.from) break;
        width = s.width.value_or(c.beam.width);
        thickness = s.thickness.value_or(c.beam.thickness);
        if (!s.layers.empty()) thickness = 0.0;
        for (const Layer& l : s.layers) thickness += l.thickness;
    }
    if (e.width > 0.0) width = e.width;
    if (!(gap > 0.0) || !std::isfinite(gap) || !(width > 0.0) || !(thickness > 0.0)) return;
    const double w = width / gap, t = thickness / gap;
    if (w >= 0.3 && w <= 30.0 && t >= 0.3 && t <= 30.0) return;
    out.push_back({"electrodes[" + std::to_string(k) + "].fringing",
                   "\"meijs-fokkema\" holds for 0.3 <= w/g <= 30 and 0.3 <= t/g <= 30; here w/g = " + number_text(w) +
                       " and t/g = " + number_text(t) + " (g the electrical gap at rest): use \"none\" or another gap"});
}

// A span [from, to] (x/l) on the beam of nonzero length, keys under `at` (each end's own range is
// the schema's); `what` names the thing for the message ("an electrode").
void check_span(std::vector<CaseProblem>& out, const std::string& at, double from, double to, const char* what) {
    const bool from_ok = std::isfinite(from) && from >= 0.0 && from < 1.0;
    const bool to_ok = std::isfinite(to) && to > 0.0 && to <= 1.0;
    if (from_ok && to_ok && !(to > from)) {
        std::string message = "must be greater than from (";
        message.append(what).append(" of zero or negative length)");
        out.push_back({at + "to", message});
    }
}

// An electrode: a span of the beam of nonzero length, a gap with room for its dielectric, a solver
// that takes an adhesive layer, the fringing formula's range, a sine's amplitude beside its bias.
void check_electrode(std::vector<CaseProblem>& out, const Case& c, std::size_t k) {
    const Electrode& e = c.electrodes[k];
    const std::string at = "electrodes[" + std::to_string(k) + "].";
    check_span(out, at, e.from, e.to, "an electrode");
    if (std::isfinite(e.dielectric_thickness) && std::isfinite(e.gap) && e.gap > 0.0 && e.dielectric_thickness >= e.gap) {
        out.push_back({at + "dielectric_thickness", "must be smaller than the gap (" + number_text(e.gap) +
                                                        " m, electrode to beam, dielectric included)"});
    }
    if (e.work_of_adhesion && c.solver.method == SolverSettings::Method::exact) {
        out.push_back({"solver.method", "\"exact\" cannot take the adhesive dielectric contact of " + at +
                                            "work_of_adhesion (its law is not one of the exact solver's linear "
                                            "forms); use \"cvode\" or \"auto\""});
    }
    check_fringing_range(out, c, k);
    const Waveform& w = e.waveform;
    if (w.kind == Waveform::Kind::sine && w.bias != 0.0 && !(e.voltage > 0.0)) {
        out.push_back({at + "voltage", "must be positive with waveform = \"sine\" and a bias (the amplitude)"});
    }
    if (!built_from_shape(w.kind)) check_time_function(out, at, e.time);
}

// The explicit film spans need the gas (docs/squeeze-film.md §1) and lie on the beam with nonzero
// length, like an electrode's.
void check_films(std::vector<CaseProblem>& out, const Case& c) {
    if (c.films.size() > kMaxElectrodes) {
        out.push_back({"films[" + std::to_string(kMaxElectrodes) + "]",
                       "a case may have at most " + std::to_string(kMaxElectrodes) + " films"});
    }
    for (std::size_t k = 0; k < std::min(c.films.size(), kMaxElectrodes); ++k) {
        const Film& m = c.films[k];
        if (!c.air) {
            out.push_back({"films[" + std::to_string(k) + "]", "needs an [air] table (the gas the film is made of)"});
        }
        check_span(out, "films[" + std::to_string(k) + "].", m.from, m.to, "a film");
    }
}

// Residual stress and mid-plane stretching need both ends to hold the axis: at a free end an axial
// stress relaxes and the beam stretches nothing. A compressive stress must stay below the Euler
// buckling stress of the beam's end conditions (the finite-element model buckles a little above it,
// a Ritz bound, so every accepted stress leaves K positive definite).
void check_axial(std::vector<CaseProblem>& out, const Case& c) {
    const Beam& b = c.beam;
    if (!b.axis_held()) {
        require_finite(out, "beam.residual_stress", b.residual_stress);
        if (b.residual_stress != 0.0) {
            out.push_back({"beam.residual_stress", "needs both ends clamped or pinned (at a free end an axial "
                                                   "stress relaxes; a cantilever carries none)"});
        }
        if (b.stretching) {
            out.push_back({"beam.stretching", "needs both ends clamped or pinned (a beam with a free end does "
                                              "not stretch as it bends)"});
        }
        return;
    }
    // A beam of sections buckles at its finite-element Euler load (problem/buckling_check.hpp).
    const double critical = b.sections.empty() ? buckling_stress(c) : 0.0;
    if (std::isfinite(b.residual_stress) && critical > 0.0 && b.residual_stress <= -critical) {
        out.push_back({"beam.residual_stress", "is a compression at or beyond buckling: the beam buckles at -" +
                                                   number_text(critical) +
                                                   " Pa (Euler: E I beta^2 / A, beta l = pi pinned-pinned, 4.493 "
                                                   "clamped-pinned, 2 pi clamped-clamped)"});
    }
}

// Supports: at most kMaxSupports (the pairwise checks are quadratic in the count), none at a fixed
// end, none two at one place and side, opposite ones leaving room for the beam.
void check_supports(std::vector<CaseProblem>& out, const Case& c) {
    const std::size_t supports = std::min(c.supports.size(), kMaxSupports);
    if (c.supports.size() > kMaxSupports) {
        out.push_back({"supports[" + std::to_string(kMaxSupports) + "]",
                       "a case may have at most " + std::to_string(kMaxSupports) + " supports (it has " +
                           std::to_string(c.supports.size()) + "): every set of closed contacts is a dense eigen "
                           "problem (docs/case-files.md, Limits)"});
    }
    for (std::size_t i = 0; i < supports; ++i) {
        const Support& s = c.supports[i];
        if (at_fixed_end(c, s.position)) out.push_back({support_key(i, "position"), "a support at a clamped or pinned end never moves"});
        check_adhesion(out, c, i);
        for (std::size_t j = 0; j < i; ++j) {
            const Support& o = c.supports[j];
            if (o.side == s.side && std::abs(o.position - s.position) <= 1e-12) {
                out.push_back({support_key(i, "position"),
                               "two supports at the same place and side (supports[" + std::to_string(j) + "])"});
            }
        }
    }
    if (c.supports.size() <= kMaxSupports) check_opposite_supports(out, c.supports);
}

void check_solver(std::vector<CaseProblem>& out, const SolverSettings& s) {
    if (s.horizon > 0.0 && s.output_step > s.horizon) {
        out.push_back({"solver.output_step", "must not exceed solver.horizon (" + number_text(s.horizon) + " s)"});
    }
}

}  // namespace

double buckling_stress(const Case& c) {
    const Beam& b = c.beam;
    if (!b.axis_held() || !(b.length > 0.0) || !(b.area() > 0.0)) return 0.0;
    // Lowest root beta l of the buckling equation: pi (pinned-pinned), 4.4934... = tan's first
    // positive fixed point (clamped-pinned), 2 pi (clamped-clamped).
    constexpr double pi = 3.14159265358979323846;
    const int clamps = (b.left == EndCondition::clamped) + (b.right == EndCondition::clamped);
    const double beta_l = clamps == 0 ? pi : clamps == 1 ? 4.493409457909064 : 2.0 * pi;
    const double beta = beta_l / b.length;
    return c.material.effective_modulus() * b.second_moment() * beta * beta / b.area();
}

bool bending_is_restrained(EndCondition left, EndCondition right) {
    // One clamp, or two pins, is the least that stops both rigid-body bending motions.
    if (left == EndCondition::clamped || right == EndCondition::clamped) return true;
    return left == EndCondition::pinned && right == EndCondition::pinned;
}

std::vector<CaseProblem> check_case(const Case& c) {
    std::vector<CaseProblem> out;
    // Every key's own value, from the schema: finite, in its range, in the magnitude window.
    check_key_values(out, c);
    if (!bending_is_restrained(c.beam.left, c.beam.right)) {
        out.push_back({"beam.right",
                       "the end conditions leave the beam free to move as a rigid body "
                       "(needs a clamped end or two pinned ends)"});
    }
    check_supports(out, c);
    const RayleighDamping& d = c.damping;
    if (d.from_ratios && d.mode1 == d.mode2) out.push_back({"damping.modes", "the two modes must differ"});
    check_axial(out, c);
    check_sections(out, c);
    check_initial(out, c);
    for (std::size_t k = 0; k < c.loads.size(); ++k) check_load(out, c, k);
    if (c.electrodes.size() > kMaxElectrodes) {
        out.push_back({"electrodes[" + std::to_string(kMaxElectrodes) + "]",
                       "a case may have at most " + std::to_string(kMaxElectrodes) + " electrodes"});
    }
    for (std::size_t k = 0; k < std::min(c.electrodes.size(), kMaxElectrodes); ++k) check_electrode(out, c, k);
    check_films(out, c);
    check_solver(out, c.solver);
    for (const SectionSpec& s : case_schema().sections) {
        if (s.check) s.check(out, c);
    }
    if (c.supports.size() <= kMaxSupports) check_magnitudes(out, c);
    return out;
}

}  // namespace vi
