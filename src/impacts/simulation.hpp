#pragma once
// One transient run of a case from start to summary: build, solve (the exact solver or CVODE, behind
// TransientSolver), summarise (the impact ledger, and the switching ledger under electrode voltage).

#include <functional>
#include <optional>
#include <vector>

#include "impacts/impact_summary.hpp"
#include "impacts/switching_ledger.hpp"
#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_solver.hpp"
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
    // The whole beam's deflection (history.field) at solver.field_step, or at horizon / 200 where the
    // case gives none; only with the history. Off by default, so that sweeps and fits of a case with a
    // field_step do not record one at every run.
    bool field = false;
    // Called with the time the solver has reached [s] as it goes (TransientOptions::progress); empty: none.
    std::function<void(double)> progress;
    // Makes the run's stop test (TransientOptions::stop_when) once the problem is built, e.g.
    // settled_stop (impacts/settled_stop.hpp); empty, or returning an empty test: to the horizon.
    std::function<std::function<bool(const RunSoFar&)>(const Case&, const BuiltProblem&)> stop_when;
    // The number of leading impacts whose peaks the caller reads (-1: every episode's). Later
    // episodes' peaks are then only compared with the settle threshold (impacts/peak_demand.hpp):
    // the summary's T_p and its first impacts are as with every peak, the later impacts' peak force
    // and penetration NaN where not computed. Exact solver, cases without electrodes; else ignored.
    int peak_impacts = -1;
};

// Bounds of the field output: frames (one file each) and values held in memory (8 bytes each).
inline constexpr long kMaxFieldFrames = 5000;
inline constexpr double kMaxFieldValues = 4e6;

// Every how many history samples a frame of the field is taken, from the case's field_step (or
// horizon / 200 when none is given), rounded to whole output steps. Throws InputError naming
// solver.field_step when the frames of `dofs` values break the bounds above.
long field_every(const SolverSettings& s, int dofs);

// The options of a transient run from the case's [solver] table: the common ones, and CVODE's.
TransientOptions transient_options(const SolverSettings& s, const SimulationOptions& o = {});
CvodeOptions cvode_options(const SolverSettings& s);

// How the case's impacts are summarised (omega1, grouping, settling, equilibria): what summarize_impacts takes.
ImpactSettings impact_settings(const Case& c, const BuiltProblem& b);

// Runs the case's transient on the solver it chooses (solver.method), CVODE where the exact solver
// gives up and solver.fallback allows. Throws InputError when the case cannot run (no horizon, a
// horizon too short to see the first impact, a limit of check_transient_run, checked before any
// work) and std::runtime_error on numerical trouble.
SimulationRun run_simulation(const Case& c, const SimulationOptions& o = {});

// Every contact of the model, in the result's order, with what holds it where it is adhesive: what
// switching_ledger takes.
std::vector<LedgerContact> ledger_contacts(const Case& c, const BeamModel& m);

}  // namespace vi
