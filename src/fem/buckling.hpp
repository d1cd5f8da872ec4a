#pragma once
// The Euler buckling force of an assembled beam [N]: the least compression its straight state bears.

#include "fem/system.hpp"

namespace vi {

// The least compressive axial force P [N] at which the straight beam of s buckles: the least lambda
// with (K0 - lambda G) phi = 0 over the bending DOFs, K0 the stiffness without the axial force's
// N0 G. The finite-element value is a Ritz bound (a little above the exact one, converging like h^4),
// so every compression below it leaves K positive definite. Throws std::runtime_error when K0 is not
// positive definite or the inverse iteration does not settle within its bound of steps.
double buckling_force(const System& s);

}  // namespace vi
