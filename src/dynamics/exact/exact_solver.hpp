#pragma once
// Exact event-driven solver: within each contact state the response is a sum of modal exponentials
// (decomposed once per state and reused); only the switching instants are found by root finding.

#include <cstddef>

#include "dynamics/piecewise_linear_problem.hpp"
#include "dynamics/transient_problem.hpp"
#include "dynamics/transient_result.hpp"

namespace vi {

struct ExactOptions {
    bool energy = true;           // energy ledger and energy history (costs O(n^2) per sample)
    bool history = true;          // sample the time history at the output step
    double h_min_periods = 1e-9;  // smallest search step, in periods of the first free mode
    long max_events = 1000000;    // pieces (contact switches, load breakpoints) before WorkLimitReached
    long max_steps = 50000000;    // search evaluations before WorkLimitReached
    // Memory for decomposed contact states kept for reuse [bytes]; the least recently used go first
    // and are decomposed again when met again. 1 GiB: some 6 states with the energy ledger at
    // m = 400 (each O(n^2) complex matrices, n ~ 2m), hundreds at the paper's m = 50.
    std::size_t state_cache_bytes = std::size_t{1} << 30;
};

// Solves the problem from t = 0 to p.t_end. Throws std::runtime_error on numerical trouble (a state
// that cannot be decomposed, resonant undamped forcing), WorkLimitReached when max_events or
// max_steps is reached, and StopRequested / TimeLimitReached from check_run() (model/run_control.hpp).
TransientResult solve_exact(const PiecewiseLinearProblem& p, const ExactOptions& o = {});

// The same for a problem of force elements: each describes itself as a piecewise-linear term
// (dynamics/piecewise_linear_form.hpp); InputError on solver.method names one that cannot.
TransientResult solve_exact(const TransientProblem& p, const ExactOptions& o = {});

}  // namespace vi
