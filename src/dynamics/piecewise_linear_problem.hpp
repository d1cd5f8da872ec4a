#pragma once
// PiecewiseLinearProblem: a transient problem in the exact solver's terms (dynamics/exact/), over the
// bending DOFs: unilateral Kelvin-Voigt contacts and prescribed loads, made from a TransientProblem
// by piecewise_linear_form.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "model/time_function.hpp"
#include "fem/system.hpp"

namespace vi {

// A Kelvin-Voigt support acting on one transverse DOF. With sign = +1 (below) or -1 (above) and
// the surface at height `surface` in beam coordinates: penetration d = sign (surface - v),
// dd/dt = -sign dv/dt, force magnitude F = Kc d + Cc dd/dt, force on the DOF sign F
// = Kc (surface - v) - Cc dv/dt. It acts only while d > 0 and F > 0 (no tension).
struct ContactElement {
    std::string name;        // its case key, for messages ("supports[0]")
    int dof = -1;            // index into the problem's DOF vector
    double sign = 1.0;       // +1 below, -1 above
    double surface = 0.0;    // height of the support surface in v [m]
    double stiffness = 0.0;  // Kc [N/m]
    double damping = 0.0;    // Cc [N s/m]
    double x = 0.0;          // position along the beam [m] (for output)
};

// Q(t) = amplitude * g(t) distributed as the consistent load vector `shape` (unit force) [N].
struct LoadTerm {
    Eigen::VectorXd shape;   // consistent nodal load of a unit force, over the problem's DOFs
    double amplitude = 0.0;  // [N]
    TimeFunction time;
};

// M q'' + C q' + K q = sum_k Q_k(t) + contact forces, with C = alpha M + beta K, on the bending DOFs.
struct PiecewiseLinearProblem {
    Eigen::MatrixXd M;                 // [kg], dense: bending DOFs only (n x n)
    Eigen::MatrixXd K;                 // [N/m]
    double alpha = 0.0;                // Rayleigh mass coefficient [1/s]
    double beta = 0.0;                 // Rayleigh stiffness coefficient [s]
    std::vector<ContactElement> contacts;
    std::vector<LoadTerm> loads;       // act for t >= 0 (the static step load is gone at t = 0)
    Eigen::VectorXd q0;                // initial displacement [m, rad]
    Eigen::VectorXd v0;                // initial velocity [m/s, rad/s]
    std::vector<bool> active0;         // which contacts are closed at t = 0
    int watched_dof = -1;              // DOF of the watched point's v (free end, mid-span, ...), for output
    double t_end = 0.0;                // horizon [s]
    double output_step = 0.0;          // sampling step of the time history [s]
    [[nodiscard]] int size() const { return static_cast<int>(M.rows()); }
};

}  // namespace vi
