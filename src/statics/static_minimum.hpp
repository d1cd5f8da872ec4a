#pragma once
// The static state a conservative beam settles into from a given start: a local minimum of its total
// potential energy, found downhill (for laws with softening branches, such as adhesion's, where the
// active-set Newton iteration of solve_static can run up a branch it cannot leave).

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "statics/static_solution.hpp"
#include "forces/force_set.hpp"

namespace vi {

// Pi(q) = q^T K q / 2 - f_ext^T q + sum of the stored energies of the elements that act in the
// static state (ForceElement::in_static_state), each in its static mode at q. From q = start:
// Newton steps on the gradient K q - f_ext - f_el(q), with the tangent K - df/dq shifted by a
// multiple of its diagonal where it is not positive definite (so each step goes downhill), and a
// backtracking line search on Pi. Converged when the gradient is at `tolerance` of the largest sum
// of magnitudes of its terms in a row. Throws WorkLimitReached (naming solver.max_static_iterations)
// after max_iterations steps, std::runtime_error when no step lowers Pi or the residual.
StaticState minimize_static_energy(const Eigen::SparseMatrix<double>& K, const ForceSet& forces,
                                   const Eigen::VectorXd& f_ext, Eigen::VectorXd start, int max_iterations,
                                   double tolerance = 1e-11);

// Pi at q (the same terms) [J].
double static_potential(const Eigen::SparseMatrix<double>& K, const ForceSet& forces, const Eigen::VectorXd& f_ext,
                        const Eigen::VectorXd& q);

}  // namespace vi
