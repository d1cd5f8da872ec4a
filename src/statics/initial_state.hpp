#pragma once
// How a transient starts (paper, section 3): the equilibrium the beam rests in, the static step (a
// point force lifting one point, or a given force) and the initial velocity field.

#include <Eigen/Dense>
#include <vector>

#include <Eigen/SparseCore>

#include "statics/static_solution.hpp"
#include "forces/force_set.hpp"
#include "model/case.hpp"

namespace vi {

// How the transient starts.
struct InitialConditions {
    StaticState equilibrium;         // no static load: prestressed supports may push
    StaticState stepped;             // q0 and the element modes at t = 0
    Eigen::VectorXd v0;              // initial velocity [m/s, rad/s]
    double force = 0.0;              // static point force of the step [N]
    double lift = 0.0;               // v at the point, stepped minus equilibrium [m]
};

// The equilibrium, the static step of init (rest, displacement or force at init.position) and the
// initial velocity. shape: unit point load at init.position over the bending DOFs; is_v: which
// bending DOFs are transverse; mode: the mass-normalised unsupported bending mode init.velocity_mode
// (used only for Velocity::mode); max_iterations: solver.max_static_iterations. Throws InputError
// naming initial.displacement (or initial.force) when the step presses the beam into a contact that
// does not touch at equilibrium (one that pushes against the lift), and naming
// initial.velocity_mode when that mode does not move at the point.
InitialConditions initial_conditions(const InitialState& init, const Eigen::SparseMatrix<double>& K,
                                     const ForceSet& forces, const Eigen::VectorXd& shape,
                                     const std::vector<bool>& is_v, const Eigen::VectorXd& mode, int max_iterations);

}  // namespace vi
