#include "impacts/dynamic_pullin.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "model/run_estimate.hpp"

namespace vi {
namespace {

std::string volts(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.6g V", v);
    return buf;
}

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

StepBisection bisect_step_voltage(const std::function<StepTrial(double)>& trial, double lo, double hi,
                                  const StepBisectionOptions& o) {
    if (!(lo > 0.0) || !(hi > lo)) throw std::invalid_argument("bisect_step_voltage: need 0 < lower < upper");
    StepBisection b;
    const auto run = [&](double v) {
        check_run();
        b.trials.push_back(trial(v));
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
    CvodeOptions co;
    co.rtol = k.solver.rtol;
    co.max_steps = k.solver.max_steps;
    co.max_events = k.solver.max_events;
    co.reduced_modes = k.solver.reduced_modes;
    // The first contact answers the question; the bouncing after it (grazing contacts near the
    // threshold chatter for millions of steps) is not needed.
    co.stop_at_first_contact = true;
    const auto start = std::chrono::steady_clock::now();
    StepTrial t;
    t.voltage = voltage;
    t.how = "open";
    t.reduced_modes = k.solver.reduced_modes;
    try {
        const TransientResult r = solve_cvode(built.problem, co);
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

// The reduced model's final bracket b run again on the full model: its upper end over the whole
// horizon (it ends at the closure or collapse), then its lower end over the time the upper end took
// to pull in plus one period of mode 1. That is the first approach to the threshold, where the two
// models can part; the later swings were followed by the reduced model over the whole horizon, and
// the full model differs from it only in the modes it cuts, which respond quasi-statically (docs/
// electrostatics.md §6). Agreeing at both ends, b stands (out.confirmed); otherwise the full model
// bisects on from what its trials showed, and b becomes its bracket. Returns every trial run.
std::vector<StepTrial> confirm_on_full_model(const Case& c, StepBisection& b, DynamicPullinResult& out,
                                             const DynamicPullinOptions& o, double lo, double period) {
    std::vector<StepTrial> trials = b.trials;
    check_run();
    trials.push_back(case_step_trial(c, b.upper, out.horizon, o.criterion, 0));
    const StepTrial above = trials.back();
    if (above.closes) {
        const double first_approach = std::min(out.horizon, *above.closing_time + period);
        check_run();
        trials.push_back(case_step_trial(c, b.lower, first_approach, o.criterion, 0));
    }
    const bool below_holds = above.closes && !trials.back().closes;
    out.confirmed = below_holds;
    if (out.confirmed) return trials;
    // Where the full model parts from the reduced one, it decides: a lower end that pulls in moves
    // the bracket down, an upper end that holds moves it up.
    const double from = above.closes ? lo : b.upper;
    const double to = above.closes ? b.lower : out.static_voltage;
    const auto full = [&](double v) { return case_step_trial(c, v, out.horizon, o.criterion, 0); };
    b = bisect_step_voltage(full, from, to, o.bisection);
    trials.insert(trials.end(), b.trials.begin(), b.trials.end());
    return trials;
}

}  // namespace

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
    const double period = 2.0 * std::numbers::pi / m.omega1;
    if (!(out.horizon > 0.0)) out.horizon = 10.0 * period;
    const double lo = o.lower_fraction * static_voltage;
    const auto modes = static_cast<int>(m.M.rows());
    const bool reduce = c.solver.reduced_modes == 0 && o.reduced_modes > 0 && modes > 2 * o.reduced_modes;
    out.bisected_on = reduce ? o.reduced_modes : c.solver.reduced_modes;
    out.reduced_modes = c.solver.reduced_modes;
    const auto on = [&](int model) {
        return [&c, &out, &o, model](double v) { return case_step_trial(c, v, out.horizon, o.criterion, model); };
    };
    StepBisection b = bisect_step_voltage(on(out.bisected_on), lo, static_voltage, o.bisection);
    if (reduce) {
        b.trials = confirm_on_full_model(c, b, out, o, lo, period);
    }
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
