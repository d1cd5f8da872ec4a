#include "impacts/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/exact/exact_give_up.hpp"
#include "dynamics/exact/exact_solver.hpp"
#include "impacts/peak_demand.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"
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

ExactOptions exact_options(const SolverSettings& s) {
    ExactOptions x;
    x.h_min_periods = s.min_search_step;
    return x;
}

// The solver the case chooses, and CVODE's answer where the exact solver gives up on a run it
// cannot finish (solver.fallback).
TransientResult solve_transient(const Case& c, const TransientProblem& p, const TransientOptions& o) {
    const CvodeSolver cvode(cvode_options(c.solver));
    if (!use_exact(c, p)) return cvode.solve(p, o);
    try {
        return ExactSolver(exact_options(c.solver)).solve(p, o);
    } catch (const ExactSolverGaveUp& e) {
        // The same model by the other solver (they agree to about 1e-9 where both run,
        // docs/model.md §13): an answer, with why it came from CVODE in the summary.
        if (c.solver.fallback == SolverSettings::Fallback::none) {
            throw std::runtime_error(std::string(e.what()) + "; solver.fallback = \"cvode\" computes the run with CVODE instead");
        }
        TransientResult r = cvode.solve(p, o);
        r.stats.fallback_reason = e.what();
        return r;
    }
}

// Released at rest from its own static equilibrium with nothing acting after t = 0: nothing ever
// moves, and that is the answer, not a horizon too short (tests/cases/rest_on_support.toml).
bool released_at_rest(const BuiltProblem& b) {
    const TransientProblem& p = b.problem;
    const bool loaded = std::any_of(p.forces.begin(), p.forces.end(), [](const ForceElementPtr& e) { return !e->in_static_state(); });
    const Eigen::VectorXd& q_eq = b.start.q_equilibrium;
    const double q_scale = std::max(q_eq.lpNorm<Eigen::Infinity>(), p.q0.lpNorm<Eigen::Infinity>());
    return !loaded && p.v0.isZero(0.0) &&
           (p.q0 - q_eq).lpNorm<Eigen::Infinity>() <= 64.0 * std::numeric_limits<double>::epsilon() * q_scale;
}

// A free transient (no electrode) that never touches a contact it has: the horizon was too short.
void require_first_impact(const Case& c, const SimulationRun& run, bool at_rest) {
    const TransientProblem& p = run.built.problem;
    bool touching_at_start = false;
    for (std::size_t i = 0; i < p.forces.size(); ++i) {
        const ForceElement& e = *p.forces[i];
        if (e.is_contact() && i < p.modes0.size() && p.modes0[i] == e.contact_mode()) touching_at_start = true;
    }
    // Under voltage, a switch that never closes is an answer of its own (the switching ledger says so).
    const bool actuated = !c.electrodes.empty();
    if (run.result.episodes.empty() && !touching_at_start && !run.built.model.contacts.empty() && !at_rest && !actuated) {
        throw InputError("solver.horizon: too short to see the first impact (no contact before " +
                         std::to_string(p.t_end * 1e6) + " us)");
    }
}

}  // namespace

ImpactSettings impact_settings(const Case& c, const BuiltProblem& b) {
    ImpactSettings s;
    s.omega1 = b.model.omega1;
    s.group_gap = c.solver.group_gap;
    s.settle_tolerance = c.solver.settle_tolerance;
    s.group = c.solver.grouping == SolverSettings::Grouping::flights;
    s.settle_by_velocity = c.solver.settle_rule == SolverSettings::SettleRule::velocity;
    s.settle_velocity = c.solver.settle_velocity;
    s.length = c.beam.length;
    const Eigen::VectorXd& q_eq = b.start.q_equilibrium;
    if (b.problem.watched_dof >= 0) s.tip_equilibrium = q_eq[b.problem.watched_dof];
    if (!b.model.contacts.empty()) s.contact_equilibrium = q_eq[b.model.forces[b.model.contacts.front().element]->dofs().front()];
    return s;
}

std::vector<LedgerContact> ledger_contacts(const Case& c, const BeamModel& m) {
    std::vector<LedgerContact> out;
    for (const NamedContact& k : m.contacts) {
        LedgerContact& lc = out.emplace_back(LedgerContact{k.name, std::nullopt, std::nullopt});
        const std::size_t i = k.entry.index;
        if (k.entry.table == "supports" && c.supports[i].adhesion != Adhesion::none) {
            lc.hold = contact_hold(m.system, c, i);
        } else if (k.entry.table == "electrodes" && c.electrodes[i].work_of_adhesion) {
            lc.layer = layer_hold(c, i);
        }
    }
    return out;
}

TransientOptions transient_options(const SolverSettings& s, const SimulationOptions& o) {
    TransientOptions t;
    t.history = o.history;
    t.energy = o.energy;
    t.max_steps = s.max_steps;
    t.max_events = s.max_events;
    t.progress = o.progress;
    return t;
}

CvodeOptions cvode_options(const SolverSettings& s) {
    CvodeOptions c;
    c.rtol = s.rtol;
    c.reduced_modes = s.reduced_modes;
    return c;
}

long field_every(const SolverSettings& s, int dofs) {
    const double out = s.output_step > 0.0 ? s.output_step : s.horizon / 2000.0;
    const double step = s.field_step > 0.0 ? s.field_step : s.horizon / 200.0;
    const double samples = std::floor(s.horizon / out * (1 + 1e-12)) + 1;
    const double every = std::max(1.0, std::round(step / out));
    const double frames = std::ceil(samples / every) + 1;
    const double values = frames * dofs;
    if (frames > static_cast<double>(kMaxFieldFrames) || values > kMaxFieldValues) {
        throw InputError("solver.field_step: " + significant(frames, 3) + " frames of " + std::to_string(dofs) +
                         " values each exceed the field's bounds (" + std::to_string(kMaxFieldFrames) + " frames, " +
                         significant(kMaxFieldValues, 2) + " values, " + significant(kMaxFieldValues * 8 / 1e6, 2) +
                         " MB); raise solver.field_step");
    }
    return static_cast<long>(every);
}

SimulationRun run_simulation(const Case& c, const SimulationOptions& o) {
    if (!(c.solver.horizon > 0.0)) throw InputError("solver.horizon: required for a transient (e.g. \"200 us\")");
    // What this machine or double precision cannot do is refused before any work.
    const auto limits = check_transient_run(c, o.history, memory_budget_bytes());
    if (!limits.empty()) throw InputError(limits.front().key + ": " + limits.front().message);
    SimulationRun run;
    run.built = build_transient_problem(c);
    TransientOptions to = transient_options(c.solver, o);
    to.field_every = o.field && o.history ? field_every(c.solver, run.built.problem.size()) : 0;
    if (o.stop_when) to.stop_when = o.stop_when(c, run.built);
    // The switching ledger lists every contact's peak force: with electrodes every peak is computed.
    const ImpactSettings settings = impact_settings(c, run.built);
    if (o.peak_impacts >= 0 && c.electrodes.empty()) to.peak_level = leading_impacts_peak_level(settings, o.peak_impacts);
    run.result = solve_transient(c, run.built.problem, to);
    const bool at_rest = released_at_rest(run.built);
    require_first_impact(c, run, at_rest);
    run.summary = summarize_impacts(run.result, settings);
    if (at_rest && run.summary.impacts.empty()) {
        run.summary.Tp = 0.0;
        run.summary.Tp_reason = "at_rest";
    }
    if (!c.electrodes.empty()) {
        run.switching = switching_ledger(run.result, c.electrodes, run.built.model.omega1,
                                         ledger_contacts(c, run.built.model), run.summary.group_gap);
    }
    return run;
}

}  // namespace vi
