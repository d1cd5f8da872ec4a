#pragma once
// Design optimisation: a global search (NLopt's DIRECT-L) over the variables' box, then a local one
// (BOBYQA, or COBYLA with constraints) from the best design found, with the designs computed on
// worker threads ahead of the search by look-ahead (docs/optimization.md).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "design/design_problem.hpp"
#include "design/design_store.hpp"

namespace vi {

struct OptimizeOptions {
    int max_evaluations = 200;    // designs computed by both stages together (--max-evals)
    int global_evaluations = 0;   // of those, the global stage's; 0 = half
    double x_tolerance = 1e-4;    // the local stage ends once a step moves every variable by less
                                  // than this fraction of its range
    int threads = 0;              // worker threads (0: the CPUs this process may use); the result
                                  // does not depend on it
    std::vector<ComputedDesign> known;  // designs computed before (a journal): reused, not computed
    // Sees every design computed in this run as it finishes, one call at a time, look-ahead
    // guesses included (a journal appends it). An exception from it stops the search.
    std::function<void(const ComputedDesign&)> computed;
};

// One design of the search, in the order the search used it.
struct DesignEvaluation {
    std::size_t index = 0;
    std::string stage;            // "global" or "local"
    std::vector<double> x;        // the variables [SI]
    DesignOutcome outcome;
    bool feasible = false;
    std::optional<double> best;   // the best feasible objective so far, this one included
};

struct OptimizeResult {
    std::vector<DesignEvaluation> evaluations;
    std::optional<std::size_t> best;  // the best feasible evaluation; empty when none is feasible
    std::string global_end, local_end;  // why each stage ended
    // How the work went (depends on threads and on a journal; the fields above do not):
    int threads = 1;
    std::size_t computed = 0;       // designs computed in this run (guesses the search never used included)
    std::size_t reused = 0;         // evaluations taken from `known`
    std::size_t unused_guesses = 0; // designs computed ahead that the search never asked for
    std::size_t batches = 0;        // rounds of designs computed together (the wall time's unit)
    std::size_t look_ahead_stopped_after = 0;  // batches after which the look-ahead cost too much; 0: never
    double look_ahead_s = 0.0;      // wall time of the look-ahead's replays [s]
};

// Runs both stages. `progress`, if given, sees every evaluation as the search uses it. A design that
// fails counts as worse than every design computed so far; a broken constraint adds its relative
// violation to the worst objective seen (the global stage's penalty; the local stage gives COBYLA
// the constraints themselves). The evaluations, their order and the best design are those of a
// one-thread run for any `threads` and any `known` designs. Throws StopRequested (a signal)
// through once the running designs are abandoned; what `computed` has seen stays valid.
OptimizeResult optimize_design(const DesignProblem& p, const OptimizeOptions& o,
                               const std::function<void(const DesignEvaluation&)>& progress = {});

}  // namespace vi
