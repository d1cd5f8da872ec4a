#pragma once
// The force elements of one problem and what the solvers ask of all of them at once.

#include <vector>

#include "forces/force_element.hpp"

namespace vi {

using ForceSet = std::vector<ForceElementPtr>;

// The first element that is not piecewise linear (it rules out the exact solver), or null.
const ForceElement* first_nonlinear(const ForceSet& forces);
// Every element's time stops in (t0, t1), sorted, without duplicates closer than a few ulps.
std::vector<double> time_stops(const ForceSet& forces, double t0, double t1);
// Indices of the contact elements (episodes are reported for these, in this order).
std::vector<int> contact_indices(const ForceSet& forces);

}  // namespace vi
