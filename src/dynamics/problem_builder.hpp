#pragma once
// From a Case to a TransientProblem: bending matrices, Rayleigh damping, force elements (contacts, loads) and
// the initial state (static step, then release at t = 0).

#include <Eigen/Dense>
#include <vector>
#include <string>

#include "dynamics/transient_problem.hpp"
#include "fem/rayleigh.hpp"
#include "dynamics/film_elements.hpp"
#include "fem/system.hpp"
#include "model/case.hpp"

namespace vi {

// A TransientProblem with what went into it.
struct BuiltProblem {
    System system;                         // the beam without supports (they act as contact elements)
    TransientProblem problem;              // over system.bending, in that order
    double omega1 = 0.0;                   // first unsupported bending circular frequency [rad/s]
    RayleighCoefficients rayleigh;         // alpha, beta actually used
    std::vector<double> contact_stiffness; // Kc per support [N/m]
    std::vector<double> contact_damping;   // Cc per support [N s/m] (from damping_ratio where given)
    double y0_m = 0.0;                     // lift of the point at initial.position above equilibrium [m]
    double static_force_n = 0.0;           // static point force of the step [N] (0 at rest)
    Eigen::VectorXd q_equilibrium;         // static equilibrium over the bending DOFs [m, rad]
    std::vector<FilmRegime> films;         // each squeeze film's regime at rest, at omega1
    // The watched point (history columns <name>_m, the rebound y_max): "tip" (a free end),
    // "midspan" (a beam held at both ends) or "point" (initial.position on such a beam).
    std::string watched_name = "tip";
    double watched_x_over_l = 1.0;         // where it sits, x/l
};

// Builds the transient problem of c. Throws InputError ("key: reason") when the case fails
// check_case or describes an impossible start (a support on a fixed DOF, a step that pushes the beam
// into a support, a velocity mode with a nodal point at initial.position, a mode that does not
// exist), and std::runtime_error when a numerical step fails.
BuiltProblem build_transient_problem(const Case& c);

// Position of each reduced DOF of s among its bending DOFs (s.bending), -1 for axial DOFs.
std::vector<int> bending_positions(const System& s);

}  // namespace vi
