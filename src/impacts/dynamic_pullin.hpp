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
    std::string how;                     // "contact", "collapse", "electrode" or "open"
    int reduced_modes = 0;               // the model it ran on: 0 the full one, N a reduced one
    double seconds = 0.0;                // its wall time [s]
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
    // A case on its full model (solver.reduced_modes = 0) whose beam has more than twice this many
    // bending modes is bisected on the reduced model of this many modes (docs/model.md §13), and its
    // bracket checked on the model of twice as many (at last the full one): kept when that model
    // agrees at both ends, else the finer model bisects on and is checked in turn. 0: the case's
    // model only.
    int reduced_modes = 8;
    // Told, before a finer model bisects again (it disagreed with the bracket), how many more
    // transients that may take at most; a progress report that counted the first bisection and one
    // check grows its total by it.
    std::function<void(int)> more_trials;
};

// Transients of dynamic_pullin at most when each finer model agrees at once: the bisection from
// lower_fraction x V_PI and, on a ladder of models, the two ends checked on the next finer one
// (more_trials says when a disagreement adds more).
int most_dynamic_pullin_trials(const DynamicPullinOptions& o);

struct DynamicPullinResult {
    double static_voltage = 0.0;  // V_PI of the static tracer [V]
    double voltage = 0.0;         // V_DPI: the bracket's midpoint [V]
    double lower = 0.0, upper = 0.0;  // [V]
    double horizon = 0.0;         // [s]
    std::optional<double> upper_closing_time;  // when the upper end's transient closed [s]
    PullinCriterion criterion = PullinCriterion::close;
    std::vector<StepTrial> trials;
    // The models (0 the full one, N a reduced one of N modes): the case's own, the one the bracket
    // comes from, and the finer one that agreed at both of its ends (-1 when none was asked: the
    // case's own reduced model, or a beam too small to reduce).
    int reduced_modes = 0;
    int bisected_on = 0;   // the first model bisected on
    int model = 0;         // the model whose bisection gave the bracket
    int confirmed_on = -1;
};

// One transient of c with every electrode's waveform replaced by a step to `voltage` at t = 0 (all
// electrodes at one voltage, as the static tracer), CVODE over `horizon` without history.
// reduced_modes: the model (0 full, N > 0 reduced), or -1 for the case's own solver.reduced_modes.
StepTrial case_step_trial(const Case& c, double voltage, double horizon, PullinCriterion criterion,
                          int reduced_modes = -1);

// V_DPI of c. Throws InputError when c has no electrode or a transient limit refuses the run, and
// what bisect_step_voltage and solve_cvode throw.
DynamicPullinResult dynamic_pullin(const Case& c, double static_voltage, const DynamicPullinOptions& o = {});

}  // namespace vi
