#include "study/paper/scans.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "impacts/settled_stop.hpp"
#include "impacts/simulation.hpp"
#include "fem/system.hpp"
#include "io/text_file.hpp"
#include "modal/eigen_solver.hpp"
#include "model/golden_section.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

using Clock = std::chrono::steady_clock;

ImpactBrief brief(const Impact& im) { return {im.t_on, im.t_off, im.v_in, im.peak_force}; }

std::optional<double> times(const std::optional<double>& t, double omega1) {
    if (!t) return std::nullopt;
    return *t * omega1;
}

}  // namespace

TransientPoint run_transient_point(const Case& c, double x) {
    TransientPoint pt;
    pt.x = x;
    const auto t0 = Clock::now();
    try {
        SimulationOptions o;
        o.history = false;
        o.energy = false;
        // The scans report T_p, the first cycle, the first three impacts and the extremes: the run
        // ends once these are settled instead of bouncing on to the horizon.
        o.stop_when = [](const Case& k, const BuiltProblem& b) { return settled_stop(k, b, 3); };
        o.peak_impacts = 3;
        const SimulationRun run = run_simulation(c, o);
        const ImpactSummary& s = run.summary;
        const double l = c.beam.length;
        const double w1 = run.built.model.omega1;
        const double eq = run.built.problem.watched_dof >= 0 ? run.built.start.q_equilibrium[run.built.problem.watched_dof] : 0.0;
        pt.z_max = s.z_max;
        if (s.watched_min) pt.z_min = (*s.watched_min - eq) / l;
        pt.z_equilibrium = eq / l;
        pt.tau_p = times(s.Tp, w1);
        pt.tau = times(s.T_first, w1);
        pt.tau1 = times(s.T1_first, w1);
        pt.tau2 = times(s.T2_first, w1);
        pt.tp_reason = s.Tp_reason;
        for (std::size_t i = 0; i < s.impacts.size() && i < 3; ++i) pt.impacts.push_back(brief(s.impacts[i]));
        pt.episodes = static_cast<int>(run.result.episodes.size());
        pt.impact_count = static_cast<int>(s.impacts.size());
    } catch (const std::exception& e) {
        pt.error = one_line(e.what());
    }
    pt.seconds = seconds_since(t0);
    return pt;
}

ModalPoint run_modal_point(const Case& c, double x0, int modes, const std::vector<double>& free_omega) {
    ModalPoint pt;
    pt.x0 = x0;
    try {
        Case moved = c;
        moved.supports.front().position = x0;
        const ModalResult r = analyse_modes(build_system(moved, SupportModel::pin), modes);
        for (std::size_t i = 0; i < r.bending.size() && i < free_omega.size(); ++i) {
            pt.ratio.push_back(r.bending[i].omega / free_omega[i]);
            pt.frequency_hz.push_back(r.bending[i].frequency_hz);
            pt.features.push_back(r.bending[i].features);
        }
    } catch (const std::exception& e) {
        pt.error = one_line(e.what());
    }
    return pt;
}

FreeModes run_free_modes(const Case& c, int modes) {
    FreeModes f;
    f.result = analyse_modes(build_system(c, SupportModel::none), modes);
    for (const Mode& m : f.result.bending) f.shapes.push_back(sample_shape(f.result.system, m.shape, 8));
    f.length = c.beam.length;
    f.amplitude_scale = std::sqrt(c.material.density * c.beam.area() * c.beam.length);
    return f;
}

TypicalTransient run_typical_transient(const Case& c) {
    SimulationOptions o;
    o.history = true;
    o.energy = false;
    o.field = true;
    // At most 6000 samples: sampling costs as much as the run itself, and a figure needs no more.
    Case k = c;
    k.solver.output_step = std::max(c.solver.output_step, c.solver.horizon / 6000.0);
    const SimulationRun run = run_simulation(k, o);
    TypicalTransient t;
    t.t = run.result.history.t;
    t.tip = run.result.history.watched_v;
    t.summary = run.summary;
    t.omega1 = run.built.model.omega1;
    t.tip_equilibrium = run.built.problem.watched_dof >= 0 ? run.built.start.q_equilibrium[run.built.problem.watched_dof] : 0.0;
    t.y0 = run.built.start.y0_m;
    t.support_damping = run.built.model.contact_damping.empty() ? 0.0 : run.built.model.contact_damping.front();
    t.rayleigh_alpha = run.built.model.rayleigh.alpha;
    t.rayleigh_beta = run.built.model.rayleigh.beta;
    t.output_step = run.built.problem.output_step;
    t.field = beam_field(run.built.model.system, run.result.history);
    for (const Support& p : c.supports) t.surfaces.emplace_back(p.position * c.beam.length, p.surface);
    return t;
}

ImpactForce run_impact_force(const Case& c, double x0) {
    Case k = c;
    k.supports.front().position = x0;
    SimulationOptions sampled;
    sampled.history = true;
    sampled.energy = false;
    // The first impact of the paper's cases begins near 2.2 us and lasts about 1 us; the horizon
    // doubles until the first impact (episodes grouped as in the summary) is seen to end.
    double horizon = 6e-6;
    for (;;) {
        k.solver.horizon = horizon;
        k.solver.output_step = 2.5e-9;
        const SimulationRun run = run_simulation(k, sampled);
        const auto& impacts = run.summary.impacts;
        const bool ended = impacts.size() > 1 || (impacts.size() == 1 && !impacts.front().closed_at_end &&
                                                  impacts.front().t_off + run.summary.group_gap < horizon);
        if (!ended) {
            if (horizon >= c.solver.horizon) throw std::runtime_error("the first impact does not end within the case's horizon");
            horizon = std::min(2.0 * horizon, c.solver.horizon);
            continue;
        }
        ImpactForce f;
        f.x0 = x0;
        f.impact = impacts.front();
        f.omega1 = run.built.model.omega1;
        const TimeHistory& h = run.result.history;
        const double margin = 0.05 * (f.impact.t_off - f.impact.t_on);
        for (std::size_t i = 0; i < h.t.size(); ++i) {
            if (h.t[i] < f.impact.t_on - margin || h.t[i] > f.impact.t_off + margin) continue;
            f.t.push_back(h.t[i] - f.impact.t_on);
            f.force.push_back(h.contact_force.front()[i]);
        }
        return f;
    }
}

double pinned_first_omega(const Case& c, double x0) {
    Case moved = c;
    moved.supports.front().position = x0;
    const System s = build_system(moved, SupportModel::pin);
    // The frequencies alone (a dense solve without its eigenvectors): the same omega_1 as the full
    // modal analysis gives, which the golden-section search compares with, at half the cost.
    return all_frequencies_dense(submatrix(s.K, s.bending), submatrix(s.M, s.bending))[0];
}

RatioPeak find_ratio_peak(const Case& c, double omega1_free, double lo, double hi) {
    const GoldenSectionPeak p =
        golden_section_max([&](double x) { return pinned_first_omega(c, x) / omega1_free; }, lo, hi, 1e-9);
    return {p.x, p.value};
}

}  // namespace vi
