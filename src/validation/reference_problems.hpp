#pragma once
// Reference problems shared by the validation report and the tests: the paper's cantilever as a
// Case, and small transient problems built directly (no case file) for closed-form checks.

#include "dynamics/transient_problem.hpp"
#include "model/case.hpp"

namespace vi {

// The paper's nickel cantilever, l = 117 um, w = 30 um, t = 2 um, m elements; optionally one
// support below at x0/l = support_at (Kc = 50 N/m; only its position matters for modal work).
Case paper_cantilever(int elements, double support_at = -1.0);
// The same beam clamped at both ends.
Case clamped_clamped(int elements);

// The paper's cantilever (m elements) on a Kelvin-Voigt contact "supports[0]" at its tip (zero gap),
// released from rest in its static shape under a tip force with the tip lifted by y0 [m].
TransientProblem cantilever_drop(int m, double Kc, double Cc, double y0, double alpha, double beta, double t_end);

// One mass m [kg] on a contact "supports[0]" below at height 0, from height h [m] moving down at
// v [m/s]. The free
// state needs a positive stiffness; k0 = 1e-14 Kc changes the contact closed forms by O(1e-14).
TransientProblem single_dof_drop(double m, double Kc, double Cc, double h, double v, double t_end);

// Largest omega_1(supported) / omega_1(free) over the position of a pin on the m-element
// cantilever: coarse scan in steps of 0.02, then golden-section search. Returns {x0/l, ratio}.
std::pair<double, double> first_ratio_peak(int elements);

}  // namespace vi
