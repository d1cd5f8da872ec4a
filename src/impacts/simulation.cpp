#include "impacts/simulation.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/exact/exact_give_up.hpp"
#include "model/input_error.hpp"
#include "model/run_estimate.hpp"

namespace vi {

namespace {

// The exact solver when the case asks for it, or when it is left to choose and every force element
// is piecewise linear; CVODE otherwise.
bool use_exact(const Case& c, const TransientProblem& p) {
    switch (c.solver.method) {
        case SolverSettings::Method::exact: return true;
        case SolverSettings::Method::cvode: return false;
        case SolverSettings::Method::automatic: return first_nonlinear(p.forces) == nullptr;
    }
    return true;
}

}  // namespace

SimulationRun run_simulation(const Case& c, const SimulationOptions& o) {
    if (!(c.solver.horizon > 0.0)) throw InputError("solver.horizon: required for a transient (e.g. \"200 us\")");
    // What this machine or double precision cannot do is refused before any work.
    const auto limits = check_transient_run(c, o.history, memory_budget_bytes());
    if (!limits.empty()) throw InputError(limits.front().key + ": " + limits.front().message);
    SimulationRun run;
    run.built = build_transient_problem(c);
    const TransientProblem& p = run.built.problem;
    CvodeOptions co;
    co.rtol = c.solver.rtol;
    co.max_steps = c.solver.max_steps;
    co.max_events = c.solver.max_events;
    co.reduced_modes = c.solver.reduced_modes;
    co.energy_history = o.energy;
    if (!use_exact(c, p)) {
        run.result = solve_cvode(p, co);
    } else {
        ExactOptions eo;
        eo.history = o.history;
        eo.energy = o.energy;
        eo.h_min_periods = c.solver.min_search_step;
        eo.max_events = c.solver.max_events;
        eo.max_steps = c.solver.max_steps;
        try {
            run.result = solve_exact(p, eo);
        } catch (const ExactSolverGaveUp& e) {
            // The same model by the other solver (they agree to about 1e-9 where both run,
            // docs/model.md §13): an answer, with why it came from CVODE in the summary.
            if (c.solver.fallback == SolverSettings::Fallback::none) {
                throw std::runtime_error(std::string(e.what()) + "; solver.fallback = \"cvode\" computes the run with CVODE instead");
            }
            run.result = solve_cvode(p, co);
            run.result.stats.fallback_reason = e.what();
        }
    }
    const std::vector<int> contacts = contact_indices(p.forces);
    bool touching_at_start = false;
    bool loaded = false;
    for (std::size_t i = 0; i < p.forces.size(); ++i) {
        const ForceElement& e = *p.forces[i];
        if (e.is_contact() && i < p.modes0.size() && p.modes0[i] == e.contact_mode()) touching_at_start = true;
        if (!e.in_static_state()) loaded = true;
    }
    // Released at rest from its own static equilibrium with nothing acting after t = 0: nothing ever
    // moves, and that is the answer, not a horizon too short (shared/cases/rest_on_support.toml).
    const double q_scale = std::max(run.built.start.q_equilibrium.lpNorm<Eigen::Infinity>(), p.q0.lpNorm<Eigen::Infinity>());
    const bool at_rest = !loaded && p.v0.isZero(0.0) &&
                         (p.q0 - run.built.start.q_equilibrium).lpNorm<Eigen::Infinity>() <=
                             64.0 * std::numeric_limits<double>::epsilon() * q_scale;
    // Under voltage, a switch that never closes is an answer of its own (the switching ledger says so).
    const bool actuated = !c.electrodes.empty();
    if (run.result.episodes.empty() && !touching_at_start && !contacts.empty() && !at_rest && !actuated) {
        throw InputError("solver.horizon: too short to see the first impact (no contact before " +
                         std::to_string(p.t_end * 1e6) + " us)");
    }
    ImpactSettings s;
    s.omega1 = run.built.model.omega1;
    s.group_gap = c.solver.group_gap;
    s.settle_tolerance = c.solver.settle_tolerance;
    s.group = c.solver.grouping == SolverSettings::Grouping::flights;
    s.settle_by_velocity = c.solver.settle_rule == SolverSettings::SettleRule::velocity;
    s.settle_velocity = c.solver.settle_velocity;
    s.length = c.beam.length;
    if (p.tip_dof >= 0) s.tip_equilibrium = run.built.start.q_equilibrium[p.tip_dof];
    if (!contacts.empty()) {
        s.contact_equilibrium = run.built.start.q_equilibrium[p.forces[static_cast<std::size_t>(contacts.front())]->dofs().front()];
    }
    run.summary = summarize_impacts(run.result, s);
    if (at_rest && run.summary.impacts.empty()) {
        run.summary.Tp = 0.0;
        run.summary.Tp_reason = "at_rest";
    }
    if (actuated) {
        // The supports' contacts come first among the contacts, in case order.
        std::vector<std::optional<ContactHold>> holds(c.supports.size());
        for (std::size_t k = 0; k < c.supports.size(); ++k) {
            if (c.supports[k].adhesion != Adhesion::none) holds[k] = contact_hold(run.built.model.system, c, k);
        }
        // The electrodes' layers follow, in electrode order (dynamics/electrode_elements.hpp).
        std::vector<std::optional<LayerHold>> layers(c.supports.size());
        for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
            if (!(c.electrodes[k].dielectric_thickness > 0.0)) continue;
            layers.emplace_back();
            if (c.electrodes[k].work_of_adhesion) layers.back() = layer_hold(c, k);
        }
        run.switching =
            switching_ledger(run.result, c.electrodes, run.built.model.omega1, holds, layers, run.summary.group_gap);
    }
    return run;
}

}  // namespace vi
