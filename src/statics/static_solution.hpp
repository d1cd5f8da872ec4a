#pragma once
// Static solutions with the force elements: the equilibrium the beam rests in, and the static step
// (a point force lifting one point to a given height) a transient starts from (paper, section 3).

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

#include "forces/force_set.hpp"

namespace vi {

// A static state: the bending DOFs [m, rad] and each element's mode.
struct StaticState {
    Eigen::VectorXd q;
    std::vector<int> modes;
    int iterations = 0;  // Newton iterations taken
};

// K q = f_ext + sum of the elements' forces at (q, v = 0, t = 0), over the elements that act in the
// static state (ForceElement::in_static_state). Newton's method from q = 0 with the modes `start`
// (empty: each element's static mode at q = 0); after every step each element's mode is decided
// again from q (ForceElement::static_mode), so for piecewise-linear elements this is the active-set
// iteration and one solve per contact set. Converged when the modes stay and the residual is at
// roundoff of the terms. Throws std::runtime_error when the tangent stiffness is singular, and
// WorkLimitReached (naming solver.max_static_iterations) after max_iterations steps.
StaticState solve_static(const Eigen::SparseMatrix<double>& K, const ForceSet& forces, const Eigen::VectorXd& f_ext,
                         std::vector<int> start, int max_iterations);

// The static state with a point force P along `shape` (the consistent load of a unit force at the
// point, so that shape . q is v there) such that shape . q = target: Newton's method on (q, P)
// with the constraint as the extra equation (displacement control). Same modes, limits and errors.
struct StaticLift {
    StaticState state;
    double force = 0.0;  // P [N]
};
StaticLift solve_static_lift(const Eigen::SparseMatrix<double>& K, const ForceSet& forces, const Eigen::VectorXd& shape,
                             double target, std::vector<int> start, int max_iterations);

}  // namespace vi
