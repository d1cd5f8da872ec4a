#pragma once
// solve_cvode: the transient solver for any force element (the nonlinear path), on SUNDIALS CVODE
// (BDF) in modal coordinates: the beam's linear part is diagonal, the elements act through the
// basis rows of their DOFs, and the Newton matrix is solved by a structured direct solver
// (dynamics/cvode_linear_solver.hpp) in O(r s^2) for r basis vectors and s element DOFs. Switching
// elements (contacts) are handled by CVODE's root finding with a restart at every switch. Also the
// independent cross-check of the exact event-driven solver.

#include "dynamics/piecewise_linear_problem.hpp"
#include "dynamics/transient_problem.hpp"
#include "dynamics/transient_result.hpp"

namespace vi {

struct CvodeOptions {
    double rtol = 1e-10;        // relative tolerance of every state component
    // Absolute tolerance of each component = rtol x atol_ratio x a characteristic magnitude derived
    // from the problem (cvode_system.cpp: absolute_tolerances). Most components of the modal state
    // are small (fast vectors), so the absolute tolerance is what sets the accuracy: tying it to rtol
    // makes rtol the one knob (the paper's transient: rtol 1e-8 is within 1e-7 of the exact solver,
    // 1e-10 within 5e-9; docs/model.md §13).
    double atol_ratio = 1e-4;
    long max_steps = 50000000;  // CVODE internal steps over the whole horizon (solver.max_steps)
    long max_events = 1000000;  // contact switches over the horizon (solver.max_events)
    // 0: every bending mode (the full FE model, an exact change of coordinates); N > 0: a
    // reduced-order model on the N lowest modes plus static corrections (solver.reduced_modes).
    int reduced_modes = 0;
    // End the run at the first contact onset (the result's t_end is then that time, the episode
    // closed_at_end): a question that the first contact answers (dynamic pull-in) needs no more.
    bool stop_at_first_contact = false;
    // The energy ledger at every output sample (history.energy); off, only the initial and final
    // ledgers are kept, and each sample saves a pass over every element (6 % of the switch
    // example's transient).
    bool energy_history = true;
};

// Integrates p from 0 to p.t_end. Elements switch only at located events (their switching
// functions crossing zero upward), each followed by a restart of CVODE; an element's time stops (a
// load step, a table's corners: TimeFunction::stops) are integration stops with a restart too. The energy ledger's integrals and
// each contact's impulse are extra CVODE states. Throws std::invalid_argument for an inconsistent
// problem, std::runtime_error when CVODE fails, WorkLimitReached at solver.max_steps or
// solver.max_events, std::domain_error when a force element refuses the state reached (the beam
// reaches an electrode; the element's message included), and StopRequested / TimeLimitReached from
// check_run() (never returns a partial result).
TransientResult solve_cvode(const TransientProblem& p, const CvodeOptions& o = {});
// The same problem built for the exact solver (its contacts and loads become force elements).
TransientResult solve_cvode(const PiecewiseLinearProblem& p, const CvodeOptions& o = {});

}  // namespace vi
