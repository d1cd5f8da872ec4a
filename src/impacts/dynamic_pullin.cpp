#include "impacts/dynamic_pullin.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "impacts/simulation.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "model/run_estimate.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

std::string volts(double v) { return significant(v, 6) + " V"; }

// c with every electrode stepped to `voltage` at t = 0, over `horizon`, the supports removed for the
// electrode criterion.
Case stepped(const Case& c, double voltage, double horizon, PullinCriterion criterion) {
    Case k = c;
    for (Electrode& e : k.electrodes) {
        e.voltage = voltage;
        e.waveform = Waveform{};  // g(t) given here, not built from the case file's shape
        e.time = TimeFunction{};
        e.time.kind = TimeFunction::Kind::step;
        e.time.t_on = 0.0;
    }
    if (criterion == PullinCriterion::electrode) k.supports.clear();
    k.solver.horizon = horizon;
    k.solver.method = SolverSettings::Method::cvode;
    return k;
}

}  // namespace

int most_step_trials(double lo, double hi, const StepBisectionOptions& o) {
    // One more than the halvings to the width rel_width * lo: the midpoints round.
    const double halvings = std::ceil(std::log2((hi - lo) / (o.rel_width * lo))) + 1.0;
    if (!(halvings >= 0.0)) return 2 + std::max(o.bisections, 0);
    return 2 + static_cast<int>(std::min(halvings, static_cast<double>(std::max(o.bisections, 0))));
}

StepBisection bisect_step_voltage(const std::function<StepTrial(double)>& trial, double lo, double hi,
                                  const StepBisectionOptions& o) {
    if (!(lo > 0.0) || !(hi > lo)) throw std::invalid_argument("bisect_step_voltage: need 0 < lower < upper");
    StepBisection b;
    const auto run = [&](double v) {
        check_run();
        b.trials.push_back(trial(v));
        if (o.trial_done) o.trial_done(b.trials.back());
        return b.trials.back().closes;
    };
    if (run(lo)) throw std::runtime_error("dynamic pull-in: the lower end of the bracket, " + volts(lo) + ", already pulls in");
    if (!run(hi)) {
        throw std::runtime_error("dynamic pull-in: the upper end of the bracket, " + volts(hi) +
                                 ", does not pull in within the horizon (lengthen --horizon)");
    }
    b.lower = lo;
    b.upper = hi;
    for (int i = 0; i < o.bisections && b.upper - b.lower > o.rel_width * b.upper; ++i) {
        const double mid = 0.5 * (b.lower + b.upper);
        (run(mid) ? b.upper : b.lower) = mid;
    }
    if (b.upper - b.lower > o.rel_width * b.upper) {
        throw WorkLimitReached("dynamic pull-in: the bracket " + volts(b.lower) + " .. " + volts(b.upper) +
                               " is still wider than the relative width " + std::to_string(o.rel_width) + " after " +
                               std::to_string(o.bisections) + " bisections (raise --bisections)");
    }
    return b;
}

StepTrial case_step_trial(const Case& c, double voltage, double horizon, PullinCriterion criterion, int reduced_modes) {
    Case k = stepped(c, voltage, horizon, criterion);
    if (reduced_modes >= 0) k.solver.reduced_modes = reduced_modes;
    const auto limits = check_transient_run(k, false, memory_budget_bytes());
    if (!limits.empty()) throw InputError(limits.front().key + ": " + limits.front().message);
    const BuiltProblem built = build_transient_problem(k);
    CvodeOptions co = cvode_options(k.solver);
    // The first contact answers the question; the bouncing after it (grazing contacts near the
    // threshold chatter for millions of steps) is not needed.
    co.stop_at_first_contact = true;
    const auto start = std::chrono::steady_clock::now();
    StepTrial t;
    t.voltage = voltage;
    t.how = "open";
    t.reduced_modes = k.solver.reduced_modes;
    // Whether and when it closes is all a trial reads: no energy ledger at the samples (a pass over
    // every element per sample, about a sixth of a trial; the steps are the same without it).
    TransientOptions to = transient_options(k.solver);
    to.energy = false;
    try {
        const TransientResult r = solve_cvode(built.problem, to, co);
        if (r.ended_by) {
            // The beam collapsed onto an electrode (its pad's terminal mode): pulled in.
            t.closes = true;
            t.closing_time = r.ended_by->t;
            t.how = "collapse";
        } else if (!r.episodes.empty()) {
            t.closes = true;
            t.closing_time = r.episodes.front().t_on;
            t.how = "contact";
        }
    } catch (const std::domain_error&) {
        // solve_cvode's only domain_error: an electrode refusing the state (the beam reaches it).
        t.closes = true;
        t.how = "electrode";
    }
    t.seconds = seconds_since(start);
    return t;
}

namespace {

// The models a case on its full model is bisected on, coarsest first: the reduced model of n modes,
// then of 2n, 4n, ... while that stays below half the beam's `modes`, then the full model (0) when
// `full` (a mesh above kMaxFullModelBisectionElements ends on its finest reduced model).
std::vector<int> model_ladder(int n, int modes, bool full) {
    std::vector<int> out;
    for (int k = n; k > 0 && 2 * k <= modes; k *= 2) out.push_back(k);
    if (full || out.empty()) out.push_back(0);
    return out;
}

// Both ends of the bracket b run again on `model` over the whole horizon: true when the lower end
// still holds and the upper still pulls in there. Appends the trials; `from`, `to` get the bracket
// the finer model is known to lie in (with the end that disagreed moved out).
bool confirm_bracket(const std::function<StepTrial(double)>& trial, const StepBisection& b, double lo, double hi,
                     const StepBisectionOptions& o, std::vector<StepTrial>& trials, double& from, double& to) {
    check_run();
    trials.push_back(trial(b.upper));
    if (o.trial_done) o.trial_done(trials.back());
    if (!trials.back().closes) {
        from = b.upper;
        to = hi;
        return false;
    }
    check_run();
    trials.push_back(trial(b.lower));
    if (o.trial_done) o.trial_done(trials.back());
    if (trials.back().closes) {
        from = lo;
        to = b.lower;
        return false;
    }
    return true;
}

}  // namespace

int most_dynamic_pullin_trials(const DynamicPullinOptions& o) {
    return most_step_trials(o.lower_fraction, 1.0, o.bisection) + (o.reduced_modes > 0 ? 2 : 0);
}

DynamicPullinResult dynamic_pullin(const Case& c, double static_voltage, const DynamicPullinOptions& o) {
    if (c.electrodes.empty()) throw InputError("electrodes: dynamic pull-in needs at least one [[electrodes]]");
    if (!(static_voltage > 0.0)) throw std::invalid_argument("dynamic_pullin: the static pull-in voltage must be > 0");
    if (!(o.lower_fraction > 0.0 && o.lower_fraction < 1.0)) {
        throw std::invalid_argument("dynamic_pullin: lower_fraction must lie in (0, 1)");
    }
    DynamicPullinResult out;
    out.static_voltage = static_voltage;
    out.criterion = o.criterion;
    out.horizon = o.horizon;
    // omega1 and the size of the model do not depend on the horizon; any positive one builds.
    const double probe = c.solver.output_step > 0.0 ? c.solver.output_step : 1e-9;
    const BeamModel m = build_beam_model(stepped(c, static_voltage, probe, o.criterion));
    // Ten periods of mode 1: with the voltage on, a beam that is not pulled in within its first
    // swings is held (its largest travel comes in the first swing, the damping only lowers the later).
    if (!(out.horizon > 0.0)) out.horizon = 10.0 * 2.0 * std::numbers::pi / m.omega1;
    const double lo = o.lower_fraction * static_voltage;
    const auto modes = static_cast<int>(m.M.rows());
    // On the case's full model, the bisection runs on a reduced model and its bracket is checked on
    // the next finer one (twice the modes, at last the full model): the bracket stands once a finer
    // model agrees at both of its ends, a modal convergence check (docs/electrostatics.md §6). A
    // full model costs far more: an undamped one follows its mesh's top modes at every step.
    const bool reduce = c.solver.reduced_modes == 0 && o.reduced_modes > 0 && modes > 2 * o.reduced_modes;
    const bool full = c.beam.elements <= kMaxFullModelBisectionElements;
    const std::vector<int> ladder =
        reduce ? model_ladder(o.reduced_modes, modes, full) : std::vector<int>{c.solver.reduced_modes};
    out.reduced_modes = c.solver.reduced_modes;
    out.bisected_on = ladder.front();
    const auto on = [&](int model) {
        return std::function<StepTrial(double)>(
            [&c, &out, &o, model](double v) { return case_step_trial(c, v, out.horizon, o.criterion, model); });
    };
    StepBisection b = bisect_step_voltage(on(ladder.front()), lo, static_voltage, o.bisection);
    std::vector<StepTrial> trials = b.trials;
    out.model = ladder.front();
    for (std::size_t k = 1; k < ladder.size(); ++k) {
        double from = lo, to = static_voltage;
        if (confirm_bracket(on(ladder[k]), b, lo, static_voltage, o.bisection, trials, from, to)) {
            out.confirmed_on = ladder[k];
            break;
        }
        // The finer model parts from the coarser one: it bisects on from what it showed.
        if (o.more_trials) o.more_trials(most_step_trials(from, to, o.bisection) + (k + 1 < ladder.size() ? 2 : 0));
        b = bisect_step_voltage(on(ladder[k]), from, to, o.bisection);
        trials.insert(trials.end(), b.trials.begin(), b.trials.end());
        out.model = ladder[k];
    }
    b.trials = std::move(trials);
    out.lower = b.lower;
    out.upper = b.upper;
    out.voltage = 0.5 * (b.lower + b.upper);
    out.trials = b.trials;
    for (const StepTrial& t : b.trials) {
        if (t.voltage == b.upper) out.upper_closing_time = t.closing_time;
    }
    return out;
}

}  // namespace vi
