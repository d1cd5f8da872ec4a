#pragma once
// Dynamic (step) pull-in: the lowest voltage step that pulls the beam in, by bisection on transients
// (docs/electrostatics.md §6).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/case.hpp"

namespace vi {

// One transient under a voltage step.
struct StepTrial {
    double voltage = 0.0;                // [V]
    bool closes = false;                 // pulled in within the horizon
    std::optional<double> closing_time;  // first contact onset [s] (empty: none, or the beam reached the electrode)
    std::string how;                     // "contact", "electrode" or "open"
};

struct StepBisectionOptions {
    int bisections = 20;         // at most this many transients after the two bracket checks
    // Stop when (upper - lower) <= rel_width * upper. Finer brackets drive the trials onto the grazing
    // contact at the threshold, where CVODE can take minutes (docs/electrostatics.md §6).
    double rel_width = 1e-3;
    std::function<void(const StepTrial&)> trial_done;  // sees each transient as it ends
};

// The transients bisect_step_voltage runs at most between lo and hi: the two bracket checks and the
// bisections that bring the width to rel_width of the lower end (the stop's width is relative to
// the upper end, never below lo), within o.bisections. Depends on hi / lo only.
int most_step_trials(double lo, double hi, const StepBisectionOptions& o);

// The bracket at the end: `lower` does not pull in, `upper` does (upper - lower <= rel_width upper).
struct StepBisection {
    double lower = 0.0, upper = 0.0;  // [V]
    std::vector<StepTrial> trials;    // in the order run
};

// Bisects on `trial` between lo and hi after checking that lo does not pull in and hi does (throws
// std::runtime_error naming the failing end otherwise, and WorkLimitReached naming --bisections when
// the width is not reached). Calls check_run() before each transient.
StepBisection bisect_step_voltage(const std::function<StepTrial(double)>& trial, double lo, double hi,
                                  const StepBisectionOptions& o);

// What counts as pulling in. close: some support closes, or the beam reaches the electrode (the
// switch closes; with a stop inside the beam's sub-critical swing this is below the instability).
// electrode: the supports are removed and only the beam reaching the electrode counts (the
// instability itself).
enum class PullinCriterion { close, electrode };

struct DynamicPullinOptions {
    double horizon = 0.0;         // each transient's length [s]; 0 = 10 periods of mode 1 (unsupported)
    double lower_fraction = 0.5;  // the bracket: lower_fraction x V_PI(static) .. V_PI(static)
    PullinCriterion criterion = PullinCriterion::close;
    StepBisectionOptions bisection;
};

struct DynamicPullinResult {
    double static_voltage = 0.0;  // V_PI of the static tracer [V]
    double voltage = 0.0;         // V_DPI: the bracket's midpoint [V]
    double lower = 0.0, upper = 0.0;  // [V]
    double horizon = 0.0;         // [s]
    std::optional<double> upper_closing_time;  // when the upper end's transient closed [s]
    PullinCriterion criterion = PullinCriterion::close;
    std::vector<StepTrial> trials;
};

// One transient of c with every electrode's waveform replaced by a step to `voltage` at t = 0 (all
// electrodes at one voltage, as the static tracer), CVODE over `horizon` without history.
StepTrial case_step_trial(const Case& c, double voltage, double horizon, PullinCriterion criterion);

// V_DPI of c. Throws InputError when c has no electrode or a transient limit refuses the run, and
// what bisect_step_voltage and solve_cvode throw.
DynamicPullinResult dynamic_pullin(const Case& c, double static_voltage, const DynamicPullinOptions& o = {});

}  // namespace vi
