#pragma once
// solve_cvode: a general transient solver on SUNDIALS CVODE (BDF, dense analytic Jacobian, root
// finding for contact events). The independent cross-check of the exact event-driven solver, and
// the solver that will carry nonlinear forces.

#include "dynamics/transient_problem.hpp"
#include "dynamics/transient_result.hpp"

namespace vi {

struct CvodeOptions {
    double rtol = 1e-10;        // relative tolerance of every state component
    // Absolute tolerance of each component = atol_scale x a characteristic magnitude derived from
    // the problem (displacement: max of |q0|, the surface offsets and the static deflection under
    // the loads; velocity: that times the first natural frequency; see cvode_system.cpp).
    double atol_scale = 1e-12;
    long max_steps = 50000000;  // CVODE internal steps over the whole horizon (solver.max_steps)
    long max_events = 1000000;  // contact switches over the horizon (solver.max_events)
};

// Integrates p from 0 to p.t_end. Contacts switch only at located events (closing when d > 0 and
// F > 0 become true, opening when F falls through 0), each followed by a restart of CVODE; load
// breakpoints are integration stops with a restart too. The energy ledger's integrals and each
// contact's impulse are extra CVODE states. Throws std::invalid_argument for an inconsistent
// problem and std::runtime_error when CVODE fails (never returns a partial result).
TransientResult solve_cvode(const TransientProblem& p, const CvodeOptions& o = {});

}  // namespace vi
