#pragma once
// Closed-form Euler-Bernoulli results the FE model is validated against (independent of the FE code).

#include <vector>

namespace vi::closed_form {

// beta_n l of the first n bending modes of a clamped-free beam (roots of cos x cosh x = -1).
std::vector<double> cantilever_beta_l(int n);

// beta_n l of the first n bending modes of a clamped-clamped beam (roots of cos x cosh x = 1).
std::vector<double> clamped_clamped_beta_l(int n);

// Circular frequency [rad/s] of a bending mode with the given beta l: (beta l)^2 sqrt(EI/(rho A l^4)).
double bending_omega(double beta_l, double E, double I, double rho, double A, double l);

// Cantilever mode shape phi(x/l) (unnormalised) and its slope d phi / d(x/l) for a given beta l.
double cantilever_shape(double beta_l, double s);
double cantilever_slope(double beta_l, double s);

// Zeros in (0, 1) of the cantilever mode shape (nodal points) or of its slope, as x/l.
std::vector<double> cantilever_shape_zeros(double beta_l);
std::vector<double> cantilever_slope_zeros(double beta_l);

// beta l of the lowest bending mode of a cantilever with a pin (v = 0) at x0/l = a in (0, 1],
// from the 8x8 transfer determinant of the two spans.
double pinned_cantilever_beta_l(double a);

}  // namespace vi::closed_form
