#include "impacts/dynamic_pullin.hpp"

#include <algorithm>
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

StepTrial case_step_trial(const Case& c, double voltage, double horizon, PullinCriterion criterion) {
    const Case k = stepped(c, voltage, horizon, criterion);
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
    StepTrial t;
    t.voltage = voltage;
    t.how = "open";
    try {
        const TransientResult r = solve_cvode(built.problem, co);
        if (!r.episodes.empty()) {
            t.closes = true;
            t.closing_time = r.episodes.front().t_on;
            t.how = "contact";
        }
    } catch (const std::domain_error&) {
        // solve_cvode's only domain_error: an electrode refusing the state (the beam reaches it).
        t.closes = true;
        t.how = "electrode";
    }
    return t;
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
    if (!(out.horizon > 0.0)) {
        // Ten periods of mode 1: with the voltage on, a beam that is not pulled in within its first
        // swings is held (its largest travel comes in the first swing, the damping only lowers the later).
        // omega1 does not depend on the horizon; any positive one builds.
        const double probe = c.solver.output_step > 0.0 ? c.solver.output_step : 1e-9;
        const BeamModel m = build_beam_model(stepped(c, static_voltage, probe, o.criterion));
        out.horizon = 10.0 * 2.0 * std::numbers::pi / m.omega1;
    }
    const auto trial = [&](double v) { return case_step_trial(c, v, out.horizon, o.criterion); };
    const StepBisection b = bisect_step_voltage(trial, o.lower_fraction * static_voltage, static_voltage, o.bisection);
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
