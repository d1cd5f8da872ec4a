#pragma once
// Exact event-driven solver: within each contact state the response is a sum of modal exponentials
// (decomposed once per state and reused); only the switching instants are found by root finding.

#include <cstddef>
#include <string_view>

#include "dynamics/piecewise_linear_problem.hpp"
#include "dynamics/transient_solver.hpp"

namespace vi {

// The exact solver's own settings (the common ones are TransientOptions).
struct ExactOptions {
    double h_min_periods = 1e-9;  // smallest search step, in periods of the first free mode
    // Memory for decomposed contact states kept for reuse [bytes]; the least recently used go first
    // and are decomposed again when met again. 1 GiB: some 6 states with the energy ledger at
    // m = 400 (each O(n^2) complex matrices, n ~ 2m), hundreds at the paper's m = 50. Besides, each
    // thread keeps up to 16 MiB of them (never more than this) for its next run of the same beam
    // (dynamics/exact/state_memo.hpp).
    std::size_t state_cache_bytes = std::size_t{1} << 30;
};

// Solves the problem from t = 0 to p.t_end (TransientSolver's rules). max_steps counts search
// evaluations and max_events pieces (contact switches, load breakpoints). Its own failures:
// std::runtime_error for a state that cannot be decomposed or resonant undamped forcing,
// ExactSolverGaveUp (exact_give_up.hpp) for a run it cannot finish that CVODE can.
TransientResult solve_exact(const PiecewiseLinearProblem& p, const TransientOptions& o = {}, const ExactOptions& settings = {});

// The same for a problem of force elements: each describes itself as a piecewise-linear term
// (dynamics/piecewise_linear_form.hpp); InputError on solver.method names one that cannot.
TransientResult solve_exact(const TransientProblem& p, const TransientOptions& o = {}, const ExactOptions& settings = {});

class ExactSolver final : public TransientSolver {
public:
    explicit ExactSolver(const ExactOptions& settings = {}) : settings_(settings) {}
    [[nodiscard]] std::string_view method() const override { return "exact"; }
    [[nodiscard]] TransientResult solve(const TransientProblem& p, const TransientOptions& o) const override {
        return solve_exact(p, o, settings_);
    }

private:
    ExactOptions settings_;
};

}  // namespace vi
