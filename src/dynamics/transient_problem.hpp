#pragma once
// TransientProblem: the beam's linear part over its bending DOFs (mass, stiffness, Rayleigh
// damping) and the force elements acting on it, with the initial state and what to record. Every
// transient solver takes this; the exact solver asks the elements for their piecewise-linear form.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "forces/force_set.hpp"

namespace vi {

// M q'' + (alpha M + beta K) q' + K q = sum of the elements' forces, over the bending DOFs.
struct TransientProblem {
    Eigen::SparseMatrix<double> M;  // consistent mass [kg]
    Eigen::SparseMatrix<double> K;  // stiffness [N/m]
    double alpha = 0.0;             // Rayleigh mass coefficient [1/s]
    double beta = 0.0;              // Rayleigh stiffness coefficient [s]
    ForceSet forces;                // contacts, loads, ... (forces/)
    Eigen::VectorXd q0;             // initial displacement [m, rad]
    Eigen::VectorXd v0;             // initial velocity [m/s, rad/s]
    std::vector<int> modes0;        // each element's mode at t = 0 (empty: its initial_mode)
    int watched_dof = -1;           // DOF of the watched point's v (free end, mid-span, ...), for output
    double t_end = 0.0;             // horizon [s]
    double output_step = 0.0;       // sampling step of the time history [s]
    [[nodiscard]] int size() const { return static_cast<int>(M.rows()); }
};

}  // namespace vi
