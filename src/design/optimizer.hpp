#pragma once
// Design optimisation: a global search (NLopt's DIRECT-L) over the variables' box, then a local one
// (BOBYQA, or COBYLA with constraints) from the best design found (docs/optimization.md).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "design/design_problem.hpp"

namespace vi {

struct OptimizeOptions {
    int max_evaluations = 200;    // designs computed by both stages together (--max-evals)
    int global_evaluations = 0;   // of those, the global stage's; 0 = half
    double x_tolerance = 1e-4;    // the local stage ends once a step moves every variable by less
                                  // than this fraction of its range
};

// One computed design.
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
};

// Runs both stages. `progress`, if given, sees every evaluation as it is made. A design that fails
// counts as worse than every design computed so far; a broken constraint adds its relative
// violation to the worst objective seen (the global stage's penalty; the local stage gives COBYLA
// the constraints themselves). Throws StopRequested (a signal) through; checks nothing else.
OptimizeResult optimize_design(const DesignProblem& p, const OptimizeOptions& o,
                               const std::function<void(const DesignEvaluation&)>& progress = {});

}  // namespace vi
