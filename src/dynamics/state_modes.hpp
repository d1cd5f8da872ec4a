#pragma once
// Modal decompositions of the piecewise-linear system: the free beam and each set of closed contacts.
// State x = [eta; eta_dot] in the free beam's mass-normalised modal coordinates (q = Phi eta).

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "dynamics/transient_problem.hpp"

namespace vi {

using cd = std::complex<double>;

// Undamped modes of (K, M) with the Rayleigh ratio of each, and the contact rows of Phi.
struct BaseModes {
    Eigen::MatrixXd phi;        // n x n, mass normalised, columns are modes [1/sqrt(kg)]
    Eigen::VectorXd omega;      // [rad/s], ascending
    Eigen::VectorXd zeta;       // Rayleigh damping ratio of each mode [-]
    Eigen::VectorXcd pole_a;    // the two roots of s^2 + 2 zeta omega s + omega^2 per mode [1/s]
    Eigen::VectorXcd pole_b;
    int n = 0;
};

// Near critical damping the two poles of a mode merge and their eigenvectors become parallel;
// zeta is moved off 1 by this much there (a relative change of the damping of that mode only).
inline constexpr double kCriticalDampingGap = 1e-7;

// Real poles closer than this (relative) in a chain are merged when the exact rank-one decomposition
// of a contact state fails its check (see decompose_state).
inline constexpr double kPoleMergeGap = 1e-4;

// Solves the undamped eigenproblem of the problem's (K, M) and adds the Rayleigh ratios.
BaseModes base_modes(const TransientProblem& p);

// Eigen-decomposition of x' = A x for one set of closed contacts: A = R diag(lambda) L, L R = I.
struct StateModes {
    std::vector<bool> active;   // which contacts are closed
    Eigen::VectorXcd lambda;    // 2n eigenvalues [1/s]
    Eigen::MatrixXcd R;         // 2n x 2n right eigenvectors (columns), in x coordinates
    Eigen::MatrixXcd L;         // 2n x 2n left eigenvectors (rows), L R = I
    std::string method;         // "free", "rank-one", "dense"
    double residual = 0.0;      // max_k |A r_k - lambda_k r_k| / (|A| |r_k|), checked
};

// The system matrix A of a contact set in x coordinates (dense, 2n x 2n): for tests and fallback.
Eigen::MatrixXd state_matrix(const BaseModes& b, const TransientProblem& p, const std::vector<bool>& active);

// Decomposes the contact set: closed form for no contact, a secular-equation (Aberth) solution of
// the rank-one update for one contact, a dense eigen solve otherwise or when the fast path cannot
// verify itself. Throws std::runtime_error when even the dense path is not diagonalisable.
StateModes decompose_state(const BaseModes& b, const TransientProblem& p, const std::vector<bool>& active);

}  // namespace vi
