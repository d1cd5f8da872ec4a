#pragma once
// From a TransientProblem (force elements) to the exact solver's PiecewiseLinearProblem (unilateral
// Kelvin-Voigt supports and prescribed loads): the elements describe themselves
// (ForceElement::linear_form), no solver names a force.

#include "dynamics/piecewise_linear_problem.hpp"
#include "dynamics/transient_problem.hpp"

namespace vi {

// The problem in the exact solver's terms. Throws InputError on solver.method, naming the first
// element that is not piecewise linear.
PiecewiseLinearProblem piecewise_linear_form(const TransientProblem& p);

}  // namespace vi
