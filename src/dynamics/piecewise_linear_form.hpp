#pragma once
// Between a TransientProblem (force elements) and the exact solver's PiecewiseLinearProblem
// (unilateral Kelvin-Voigt supports and prescribed loads): the elements describe themselves
// (ForceElement::linear_form), no solver names a force.

#include "dynamics/piecewise_linear_problem.hpp"
#include "dynamics/transient_problem.hpp"

namespace vi {

// The problem in the exact solver's terms. Throws InputError on solver.method, naming the first
// element that is not piecewise linear.
PiecewiseLinearProblem piecewise_linear_form(const TransientProblem& p);

// The same problem as force elements ("supports[k]" contacts, "loads[k]" point loads): how a
// problem built directly for the exact solver (tests, closed-form references) also runs on the
// nonlinear path.
TransientProblem transient_problem_of(const PiecewiseLinearProblem& p);

}  // namespace vi
