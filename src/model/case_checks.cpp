#include "model/case_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "model/magnitude_checks.hpp"
#include "model/run_estimate.hpp"

namespace vi {
namespace {

std::string support_key(std::size_t i, const char* field) {
    return "supports[" + std::to_string(i) + "]." + field;
}

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

// x/l of a point on the beam: in (0, 1].
void require_beam_point(std::vector<CaseProblem>& out, const std::string& key, double position) {
    if (!std::isfinite(position)) {
        out.push_back({key, "must be a finite number"});
    } else if (!(position > 0.0 && position <= 1.0)) {
        out.push_back({key, "must lie in (0, 1] (x/l)"});
    }
}

// True when x/l = position is the right end and that end is clamped or pinned (v fixed there).
bool at_fixed_end(const Case& c, double position) {
    return position == 1.0 && c.beam.right != EndCondition::free;
}

std::string number_text(double v) {
    std::ostringstream s;
    s << (v == 0.0 ? 0.0 : v);  // no "-0"
    return s.str();
}

// Height of a support's surface in beam coordinates (v, positive up).
double surface_height(const Support& s) { return s.side == Side::below ? s.surface : -s.surface; }

// A support below and one above at the same place must leave room for the beam between them.
// An adhesive support: positive parameters, and a solver that takes its law (the exact solver's
// linear forms have no cohesive zone; docs/adhesion.md §3).
void check_adhesion(std::vector<CaseProblem>& out, const Case& c, std::size_t i) {
    const Support& s = c.supports[i];
    if (s.adhesion == Adhesion::none) return;
    require_positive(out, support_key(i, "work_of_adhesion"), s.work_of_adhesion);
    require_positive(out, support_key(i, "contact_radius"), s.contact_radius);
    require_positive(out, support_key(i, "adhesion_range"), s.adhesion_range);
    if (c.solver.method == SolverSettings::Method::exact) {
        std::string why = "\"exact\" cannot take the adhesive contact of ";
        why.append(support_key(i, "adhesion"))
            .append(" (its cohesive law is not one of the exact solver's linear forms); use \"cvode\" or \"auto\"");
        out.push_back({"solver.method", why});
    }
}

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
    require_beam_point(out, "initial.position", in.position);
    const bool steps = (in.kind == Kind::displacement && in.displacement != 0.0) ||
                       (in.kind == Kind::force && in.force != 0.0) ||
                       (in.velocity_kind == Velocity::mode && in.velocity != 0.0);
    if (steps && at_fixed_end(c, in.position)) {
        out.push_back({"initial.position", "lies at a clamped or pinned end, where v cannot move"});
    }
    if (in.kind == Kind::displacement) require_finite(out, "initial.displacement", in.displacement);
    if (in.kind == Kind::force) require_finite(out, "initial.force", in.force);
    if (in.velocity_kind != Velocity::none) require_finite(out, "initial.velocity", in.velocity);
    if (in.velocity_kind == Velocity::mode && in.velocity_mode < 1) {
        out.push_back({"initial.velocity_mode", "must be at least 1"});
    }
}

// The keys of a time function g(t) under `at` ("loads[0]." or "electrodes[1].").
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

// The shape keys of an electrode's waveform under `at` ("electrodes[1]."), as a case file gives them
// or a sweep sets them.
void check_waveform(std::vector<CaseProblem>& out, const std::string& at, const Waveform& w, double voltage) {
    using Kind = Waveform::Kind;
    const bool timed = w.kind == Kind::step || w.kind == Kind::ramp || w.kind == Kind::pulse || w.kind == Kind::two_step;
    if (timed) require_non_negative(out, at + "t_on", w.t_on);
    if (w.kind == Kind::ramp || w.kind == Kind::pulse || w.kind == Kind::two_step) require_positive(out, at + "rise", w.rise);
    if (w.kind == Kind::pulse || w.kind == Kind::two_step) require_positive(out, at + "hold", w.hold);
    if (w.kind == Kind::pulse) require_positive(out, at + "fall", w.fall);
    if (w.kind == Kind::two_step) require_non_negative(out, at + "level", w.level);
    if (w.kind == Kind::sine) {
        require_positive(out, at + "frequency", w.frequency);
        require_finite(out, at + "phase", w.phase);
        require_finite(out, at + "bias", w.bias);
        if (w.bias != 0.0 && !(voltage > 0.0)) {
            out.push_back({at + "voltage", "must be positive with waveform = \"sine\" and a bias (the amplitude)"});
        }
    }
}

void check_load(std::vector<CaseProblem>& out, const Case& c, std::size_t k) {
    const PointLoad& p = c.loads[k];
    const std::string at = "loads[" + std::to_string(k) + "].";
    require_beam_point(out, at + "position", p.position);
    if (at_fixed_end(c, p.position)) out.push_back({at + "position", "a load at a clamped or pinned end does nothing"});
    require_finite(out, at + "amplitude", p.amplitude);
    check_time_function(out, at, p.time);
}

// An electrode: a span of the beam of nonzero length, a gap with room for its dielectric.
// Meijs and Fokkema state their formula for 0.3 <= w/g <= 30 and 0.3 <= t/g <= 30; outside it the
// fringing force is an extrapolation nobody has checked, so a case must not rely on it. Checked at
// the electrical gap at rest (as the gap closes w/g grows past the range: docs/electrostatics.md §2).
void check_fringing_range(std::vector<CaseProblem>& out, const Case& c, std::size_t k) {
    const Electrode& e = c.electrodes[k];
    if (e.fringing != Fringing::meijs_fokkema) return;
    const double gap = (e.gap - e.dielectric_thickness) + e.dielectric_thickness / e.dielectric_permittivity;
    const double width = e.width > 0.0 ? e.width : c.beam.width;
    if (!(gap > 0.0) || !std::isfinite(gap) || !(width > 0.0) || !(c.beam.thickness > 0.0)) return;
    const double w = width / gap, t = c.beam.thickness / gap;
    if (w >= 0.3 && w <= 30.0 && t >= 0.3 && t <= 30.0) return;
    out.push_back({"electrodes[" + std::to_string(k) + "].fringing",
                   "\"meijs-fokkema\" holds for 0.3 <= w/g <= 30 and 0.3 <= t/g <= 30; here w/g = " + number_text(w) +
                       " and t/g = " + number_text(t) + " (g the electrical gap at rest): use \"none\" or another gap"});
}

// A span [from, to] (x/l) on the beam of nonzero length, keys under `at`; `what` names the thing
// for the message ("an electrode").
void check_span(std::vector<CaseProblem>& out, const std::string& at, double from, double to, const char* what) {
    if (!std::isfinite(from) || from < 0.0 || from >= 1.0) out.push_back({at + "from", "must lie in [0, 1) (x/l)"});
    if (!std::isfinite(to) || to <= 0.0 || to > 1.0) {
        out.push_back({at + "to", "must lie in (0, 1] (x/l)"});
    } else if (std::isfinite(from) && !(to > from)) {
        std::string message = "must be greater than from (";
        message.append(what).append(" of zero or negative length)");
        out.push_back({at + "to", message});
    }
}

void check_electrode(std::vector<CaseProblem>& out, const Case& c, std::size_t k) {
    const Electrode& e = c.electrodes[k];
    const std::string at = "electrodes[" + std::to_string(k) + "].";
    check_span(out, at, e.from, e.to, "an electrode");
    require_positive(out, at + "gap", e.gap);
    require_non_negative(out, at + "dielectric_thickness", e.dielectric_thickness);
    if (std::isfinite(e.dielectric_thickness) && std::isfinite(e.gap) && e.gap > 0.0 && e.dielectric_thickness >= e.gap) {
        out.push_back({at + "dielectric_thickness", "must be smaller than the gap (" + number_text(e.gap) +
                                                        " m, electrode to beam, dielectric included)"});
    }
    if (!std::isfinite(e.dielectric_permittivity) || e.dielectric_permittivity < 1.0) {
        out.push_back({at + "dielectric_permittivity", "must be at least 1 (relative permittivity)"});
    }
    if (!std::isfinite(e.width) || e.width < 0.0) out.push_back({at + "width", "must be positive"});
    require_positive(out, at + "dielectric_modulus", e.dielectric_modulus);
    if (e.work_of_adhesion) {
        require_positive(out, at + "work_of_adhesion", *e.work_of_adhesion);
        require_positive(out, at + "adhesion_range", e.adhesion_range);
        if (c.solver.method == SolverSettings::Method::exact) {
            out.push_back({"solver.method", "\"exact\" cannot take the adhesive dielectric contact of " + at +
                                                "work_of_adhesion (its law is not one of the exact solver's linear "
                                                "forms); use \"cvode\" or \"auto\""});
        }
    }
    check_fringing_range(out, c, k);
    require_finite(out, at + "voltage", e.voltage);
    if (built_from_shape(e.waveform.kind)) {
        check_waveform(out, at, e.waveform, e.voltage);
    } else {
        check_time_function(out, at, e.time);
    }
}

// The gas and the explicit film spans (docs/squeeze-film.md §1). A film span must lie on the beam
// with nonzero length, like an electrode's.
void check_air(std::vector<CaseProblem>& out, const Case& c) {
    if (c.air) {
        require_positive(out, "air.pressure", c.air->pressure);
        require_positive(out, "air.temperature", c.air->temperature);
        require_positive(out, "air.viscosity", c.air->viscosity);
        if (c.air->mean_free_path) require_positive(out, "air.mean_free_path", *c.air->mean_free_path);
    }
    if (c.films.size() > kMaxElectrodes) {
        out.push_back({"films[" + std::to_string(kMaxElectrodes) + "]",
                       "a case may have at most " + std::to_string(kMaxElectrodes) + " films"});
    }
    for (std::size_t k = 0; k < std::min(c.films.size(), kMaxElectrodes); ++k) {
        const Film& m = c.films[k];
        const std::string at = "films[" + std::to_string(k) + "].";
        if (!c.air) {
            out.push_back({"films[" + std::to_string(k) + "]", "needs an [air] table (the gas the film is made of)"});
        }
        check_span(out, at, m.from, m.to, "a film");
        require_positive(out, at + "gap", m.gap);
    }
}

// Residual stress and mid-plane stretching need both ends to hold the axis: at a free end an axial
// stress relaxes and the beam stretches nothing. A compressive stress must stay below the Euler
// buckling stress of the beam's end conditions (the finite-element model buckles a little above it,
// a Ritz bound, so every accepted stress leaves K positive definite).
void check_axial(std::vector<CaseProblem>& out, const Case& c) {
    const Beam& b = c.beam;
    require_finite(out, "beam.residual_stress", b.residual_stress);
    if (!b.axis_held()) {
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
    const double critical = buckling_stress(c);
    if (std::isfinite(b.residual_stress) && critical > 0.0 && b.residual_stress <= -critical) {
        out.push_back({"beam.residual_stress", "is a compression at or beyond buckling: the beam buckles at -" +
                                                   number_text(critical) +
                                                   " Pa (Euler: E I beta^2 / A, beta l = pi pinned-pinned, 4.493 "
                                                   "clamped-pinned, 2 pi clamped-clamped)"});
    }
}

void check_solver(std::vector<CaseProblem>& out, const SolverSettings& s) {
    // horizon and output_step: 0 stands for "not given".
    if (!std::isfinite(s.horizon) || s.horizon < 0.0) out.push_back({"solver.horizon", "must be positive"});
    if (!std::isfinite(s.output_step) || s.output_step < 0.0) {
        out.push_back({"solver.output_step", "must be positive"});
    } else if (s.horizon > 0.0 && s.output_step > s.horizon) {
        out.push_back({"solver.output_step",
                       "must not exceed solver.horizon (" + number_text(s.horizon) + " s)"});
    }
    require_non_negative(out, "solver.group_gap", s.group_gap);
    if (!(s.settle_tolerance > 0.0 && s.settle_tolerance < 1.0)) {
        out.push_back({"solver.settle_tolerance", "must lie in (0, 1)"});
    }
    if (s.settle_rule == SolverSettings::SettleRule::velocity && !(s.settle_velocity > 0.0)) {
        out.push_back({"solver.settle_velocity", "must be positive"});
    }
    if (!(s.rtol > 0.0 && s.rtol <= 1e-3)) out.push_back({"solver.rtol", "must lie in (0, 1e-3]"});
    // Below 1e-15 periods a step no longer moves the time of a piece (t + h rounds to t).
    if (!(s.min_search_step >= 1e-15 && s.min_search_step <= 1e-3)) {
        out.push_back({"solver.min_search_step", "must lie in [1e-15, 1e-3] (periods of the first mode)"});
    }
    if (!(s.max_events >= 1 && s.max_events <= 1000000000L)) {
        out.push_back({"solver.max_events", "must lie in [1, 1e9]"});
    }
    if (!(s.max_steps >= 1000 && s.max_steps <= 100000000000L)) {
        out.push_back({"solver.max_steps", "must lie in [1000, 1e11]"});
    }
    if (!(s.max_static_iterations >= 1 && s.max_static_iterations <= 1000000)) {
        out.push_back({"solver.max_static_iterations", "must lie in [1, 1e6]"});
    }
    if (!(s.reduced_modes >= 0 && s.reduced_modes <= 100000)) {
        out.push_back({"solver.reduced_modes", "must lie in [0, 1e5] (0: the full model)"});
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
    require_positive(out, "beam.length", c.beam.length);
    require_positive(out, "beam.width", c.beam.width);
    require_positive(out, "beam.thickness", c.beam.thickness);
    if (c.beam.elements < 1) out.push_back({"beam.elements", "must be at least 1"});
    if (c.beam.elements > kMaxElements) {
        out.push_back({"beam.elements", "must be at most " + std::to_string(kMaxElements) +
                                            ": the roundoff of the stiffness matrix grows like 5 m^4, so finer meshes "
                                            "only lose digits (docs/case-files.md, Limits)"});
    }
    if (!bending_is_restrained(c.beam.left, c.beam.right)) {
        out.push_back({"beam.right",
                       "the end conditions leave the beam free to move as a rigid body "
                       "(needs a clamped end or two pinned ends)"});
    }

    require_positive(out, "material.youngs_modulus", c.material.youngs_modulus);
    require_positive(out, "material.density", c.material.density);
    const double nu = c.material.poisson_ratio;
    if (!std::isfinite(nu)) {
        out.push_back({"material.poisson_ratio", "must be a finite number"});
    } else if (nu <= -1.0 || nu >= 0.5) {
        out.push_back({"material.poisson_ratio", "must lie in (-1, 0.5)"});
    }

    // Checked before the pairwise checks below, which are quadratic in the count.
    const std::size_t supports = std::min(c.supports.size(), kMaxSupports);
    if (c.supports.size() > kMaxSupports) {
        out.push_back({"supports[" + std::to_string(kMaxSupports) + "]",
                       "a case may have at most " + std::to_string(kMaxSupports) + " supports (it has " +
                           std::to_string(c.supports.size()) + "): every set of closed contacts is a dense eigen "
                           "problem (docs/case-files.md, Limits)"});
    }
    for (std::size_t i = 0; i < supports; ++i) {
        const Support& s = c.supports[i];
        if (!std::isfinite(s.position)) {
            out.push_back({support_key(i, "position"), "must be a finite number"});
        } else if (!(s.position > 0.0 && s.position <= 1.0)) {
            out.push_back({support_key(i, "position"), "must lie in (0, 1] (x0/l)"});
        }
        if (at_fixed_end(c, s.position)) out.push_back({support_key(i, "position"), "a support at a clamped or pinned end never moves"});
        if (!std::isfinite(s.surface)) out.push_back({support_key(i, "gap"), "must be a finite number"});
        require_positive(out, support_key(i, "stiffness"), s.stiffness);
        require_non_negative(out, support_key(i, "damping"), s.damping);
        if (s.damping_ratio) require_non_negative(out, support_key(i, "damping_ratio"), *s.damping_ratio);
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

    const RayleighDamping& d = c.damping;
    if (d.from_ratios) {
        require_non_negative(out, "damping.ratios", d.ratio1);
        require_non_negative(out, "damping.ratios", d.ratio2);
        if (d.mode1 < 1 || d.mode2 < 1) out.push_back({"damping.modes", "mode numbers start at 1"});
        if (d.mode1 == d.mode2) out.push_back({"damping.modes", "the two modes must differ"});
    } else {
        require_non_negative(out, "damping.alpha", d.alpha);
        require_non_negative(out, "damping.beta", d.beta);
    }
    check_axial(out, c);
    check_initial(out, c);
    for (std::size_t k = 0; k < c.loads.size(); ++k) check_load(out, c, k);
    if (c.electrodes.size() > kMaxElectrodes) {
        out.push_back({"electrodes[" + std::to_string(kMaxElectrodes) + "]",
                       "a case may have at most " + std::to_string(kMaxElectrodes) + " electrodes"});
    }
    for (std::size_t k = 0; k < std::min(c.electrodes.size(), kMaxElectrodes); ++k) check_electrode(out, c, k);
    check_air(out, c);
    check_solver(out, c.solver);
    if (c.supports.size() <= kMaxSupports) check_magnitudes(out, c);
    return out;
}

}  // namespace vi
