#pragma once
// A point mass falling onto a Hertz surface (gold on gold through a dimple of radius 2 um), the
// problem both the Hertz law's and the contact damage's closed-form tests solve.

#include <cmath>
#include <limits>
#include <memory>

#include "dynamics/cvode/cvode_solver.hpp"
#include "forces/hertz_contact.hpp"
#include "transient_fixtures.hpp"

namespace vi::test::hertz {

inline constexpr double kRadius = 2e-6;  // dimple radius [m]
inline constexpr double kMass = 1e-11;   // [kg]
inline double gold_star() { return effective_modulus(79e9, 0.42, 79e9, 0.42); }  // E* of gold on gold [Pa]
inline double gold_k() { return hertz_stiffness(gold_star(), kRadius); }          // k [N/m^(3/2)]

// Hertz's largest penetration of the mass arriving at v_in [m/s]: (5 m v^2 / (4 k))^(2/5) [m].
inline double hertz_d_max(double v_in) { return std::pow(5.0 * kMass * v_in * v_in / (4.0 * gold_k()), 0.4); }

// The mass 0.1 um from a Hertz surface at 0 (below for sign = +1, above for -1), moving to it at
// v_in [m/s] with Hunt-Crossley alpha [s/m] and the surface's yield strength [Pa] (NaN: none);
// nothing else acts. The horizon covers the impact and some time after.
inline TransientProblem falling_mass(double v_in, double alpha, double sign = 1.0,
                                     double yield_strength = std::numeric_limits<double>::quiet_NaN()) {
    const double h = 0.1e-6;
    TransientProblem p = one_dof(kMass, 0.0);
    p.forces.push_back(std::make_shared<HertzContact>("supports[0]", 0, sign, 0.0, 0.0, gold_k(), alpha, kRadius,
                                                      std::nullopt, yield_strength));
    p.q0 = Eigen::VectorXd::Constant(1, sign * h);
    p.v0 = Eigen::VectorXd::Constant(1, -sign * v_in);
    p.modes0 = {0};
    p.t_end = h / v_in + 6.0 * hertz_d_max(v_in) / v_in;
    p.output_step = p.t_end / 50;
    return p;
}

// CVODE at the tolerance the closed forms are checked to.
inline CvodeOptions tight() {
    CvodeOptions o;
    o.rtol = 1e-12;
    return o;
}

}  // namespace vi::test::hertz
