#pragma once
// One transient run of a case from start to summary: build, solve (exact or CVODE), summarise (the
// impact ledger, and the switching ledger under electrode voltage).

#include <optional>

#include "impacts/impact_summary.hpp"
#include "impacts/switching_ledger.hpp"
#include "dynamics/exact/exact_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "dynamics/transient_result.hpp"
#include "model/case.hpp"

namespace vi {

struct SimulationRun {
    BuiltProblem built;
    TransientResult result;
    ImpactSummary summary;
    std::optional<SwitchingLedger> switching;  // when the case has electrodes
};

// What to compute besides the impact characteristics.
struct SimulationOptions {
    bool history = true;  // sampled time history
    bool energy = true;   // energy ledger at every sample (exact solver: O(n^2) per sample and per piece)
};

// Runs the case's transient. Throws InputError when the case cannot run (no horizon, a horizon too
// short to see the first impact, a limit of check_transient_run, checked before any work) and
// std::runtime_error on numerical trouble.
SimulationRun run_simulation(const Case& c, const SimulationOptions& o = {});

}  // namespace vi
