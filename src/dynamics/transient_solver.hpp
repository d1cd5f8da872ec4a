#pragma once
// TransientSolver: the contract both transient solvers keep (as MFEM's ODESolver), the exact
// event-driven one (dynamics/exact/) and CVODE (dynamics/cvode/): one problem in, one result out,
// the options common to both in one struct, each solver's own settings given to its constructor.
//
// The rules:
//  - solve(p, o) integrates p (dynamics/transient_problem.hpp) from t = 0 to p.t_end and returns the
//    whole result (dynamics/transient_result.hpp): the time history at p.output_step, every contact
//    episode in onset order, the initial and final energy ledgers, the extremes, the statistics.
//  - The stop flag: every loop of a solver calls check_run() (model/run_control.hpp), so SIGINT,
//    SIGTERM or the thread's time limit end it with StopRequested or TimeLimitReached; it never
//    returns a partial result.
//  - Work bounds: more than o.max_steps steps or o.max_events events throws WorkLimitReached naming
//    solver.max_steps or solver.max_events.
//  - Failures: std::invalid_argument for an inconsistent problem, InputError for a problem the solver
//    cannot take (naming the element and solver.method), ExactSolverGaveUp where the exact solver
//    cannot finish a well-posed run (another solver can), std::domain_error where an element refuses
//    the state reached (the beam reaches an electrode), std::runtime_error for other numerical
//    trouble.

#include <functional>
#include <string_view>
#include <vector>

#include "dynamics/transient_problem.hpp"
#include "dynamics/transient_result.hpp"

namespace vi {

// What a run's stop test sees at the start of each piece of the exact solver (after a contact
// switch or a load breakpoint).
struct RunSoFar {
    double t = 0.0;                                  // [s]
    const std::vector<ContactEpisode>& episodes;     // so far, in onset order (an open one's t_off is not yet set)
    const Extremes& extremes;                        // so far
    bool all_open = false;                           // no contact closed, none still compressed after opening
    // Energy of the motion about the equilibrium of the forcing now acting, 1/2 v^T M v +
    // 1/2 (q - q_e)^T K (q - q_e) with the contacts' stiffness left out [J]; negative when the forcing varies.
    double motion_energy = -1.0;
};

struct TransientOptions {
    // The time history at the output step. The exact solver skips sampling without it; CVODE samples
    // anyway (at no cost to its steps).
    bool history = true;
    // The energy ledger at every sample (history.energy): O(n^2) per sample and per piece for the
    // exact solver, a pass over every element per sample for CVODE.
    bool energy = true;
    // The whole beam's displacement (history.field) at every field_every-th sample of the history
    // (samples 0, k, 2k, ... and the last); 0: none. Costs one solve of every DOF per frame.
    long field_every = 0;
    long max_steps = 50000000;  // solver.max_steps: steps (CVODE) or search evaluations (exact)
    long max_events = 1000000;  // solver.max_events: contact switches and load breakpoints
    // Called with the time reached [s] at each of CVODE's returns (the exact solver does not call it);
    // empty: none. For a long command's progress report: it must be cheap and must not throw but
    // what check_run throws.
    std::function<void(double)> progress;
    // Exact solver only: returns true to end the run at the time it is shown (then t_end, the
    // history and the final ledger end there); empty: the run goes to the horizon. It must be cheap
    // and must not throw. CVODE ignores it and runs to the horizon.
    std::function<bool(const RunSoFar&)> stop_when;
    // Exact solver only: how much of a contact episode's peaks the caller reads. Asked once at each
    // episode's onset with the episodes so far (the new one last), it returns a penetration [m]:
    // -inf, both peaks to the solver's tolerance (as when empty); +inf, neither (both NaN); a level,
    // only whether the penetration peak lies above it. Then both peaks are NaN when the penetration
    // is proven to stay at or below the level; when a value clearly above it is seen (beyond the
    // peak search's own tolerance), peak_penetration is that value (not the peak) and peak_force NaN;
    // otherwise the peaks are computed as usual from that piece of the episode on (the force peak
    // stays NaN if an earlier piece was skipped). Every comparison with the level comes out as with
    // full peaks, but for a peak within the search's tolerance (1e-7) of the level in an episode
    // whose earlier pieces were skipped. CVODE ignores it and computes every peak.
    std::function<double(const std::vector<ContactEpisode>&)> peak_level;
};

class TransientSolver {
public:
    virtual ~TransientSolver() = default;
    // "exact" or "cvode" (TransientResult::stats.method).
    [[nodiscard]] virtual std::string_view method() const = 0;
    [[nodiscard]] virtual TransientResult solve(const TransientProblem& p, const TransientOptions& o) const = 0;
};

}  // namespace vi
