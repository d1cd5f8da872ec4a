#pragma once
// Modal decompositions of the piecewise-linear system: the free beam and each set of closed contacts.
// State x = [eta; eta_dot] in the free beam's mass-normalised modal coordinates (q = Phi eta).

#include <Eigen/Dense>
#include <complex>
#include <string>
#include <vector>

#include "dynamics/exact/exact_give_up.hpp"
#include "dynamics/piecewise_linear_problem.hpp"

namespace vi {

using cd = std::complex<double>;

// Undamped modes of (K, M) with the Rayleigh ratio of each, and the contact rows of Phi.
struct BaseModes {
    Eigen::MatrixXd phi;        // n x n, mass normalised, columns are modes [1/sqrt(kg)]
    Eigen::VectorXd omega;      // [rad/s], ascending
    Eigen::VectorXd zeta;       // Rayleigh damping ratio of each mode [-]
    Eigen::VectorXcd pole_a;    // the two roots of s^2 + 2 zeta omega s + omega^2 per mode [1/s]
    Eigen::VectorXcd pole_b;    // (pole_a has Im >= 0; for an overdamped mode both are real)
    int n = 0;
};

// Near critical damping the two poles of a mode merge and their eigenvectors become parallel;
// zeta is moved off 1 by this much there (a relative change of the damping of that mode only).
inline constexpr double kCriticalDampingGap = 1e-7;

// Solves the undamped eigenproblem of the problem's (K, M) and adds the Rayleigh ratios.
BaseModes base_modes(const PiecewiseLinearProblem& p);

// The order of ascending |z| (the order the signal bounds split slow from fast modes by).
std::vector<int> order_by_magnitude(const std::vector<cd>& z);

// Eigen-decomposition of x' = A x, A = [0 I; -K~ -C~], for one set of closed contacts, where
// K~ = diag(omega^2) + sum Kc phi_c phi_c^T and C~ = diag(2 zeta omega) + sum Cc phi_c phi_c^T.
// Each eigenvalue z has the right eigenvector [v; z v] with (z^2 + z C~ + K~) v = 0, so only v is
// stored, and a left eigenvector row (L R = I). The system is real: its modes are `lambda` and the
// conjugates of the `paired` ones (2n in all), with conjugate vectors.
struct StateModes {
    std::vector<bool> active;       // which contacts are closed
    Eigen::VectorXcd lambda;        // m representative eigenvalues, ascending |lambda| [1/s]
    std::vector<bool> paired;       // lambda[k] stands for itself and its conjugate
    // [Re V; Im V; Re L^T; Im L^T] (6n x m; V: the displacement parts v, L: the left rows): real and
    // imaginary parts apart, as applied to real states two real products cost half of one complex
    // product, and in one block, the largest allocation of a transient. Empty when `unit` is used.
    Eigen::MatrixXd vl;
    std::vector<int> unit;          // free state: v_k is the unit vector of mode unit[k]
    Eigen::VectorXcd partner;       // free state: the other pole of mode unit[k] [1/s]
    Eigen::VectorXd damping;        // diag(2 zeta omega) [1/s]
    std::string method;             // "free", "rank-one", "dense"
    double residual = 0.0;          // worst eigenpair backward error or biorthogonality error, checked

    [[nodiscard]] int size() const { return static_cast<int>(lambda.size()); }
    [[nodiscard]] auto Vr() const { return vl.topRows(dofs()); }
    [[nodiscard]] auto Vi() const { return vl.middleRows(dofs(), dofs()); }
    [[nodiscard]] auto Lr() const { return vl.middleRows(2 * dofs(), 2 * dofs()); }
    [[nodiscard]] auto Li() const { return vl.bottomRows(2 * dofs()); }
    [[nodiscard]] int dofs() const { return static_cast<int>(damping.size()); }
    // row^T v_k for each k: how an output row^T eta reads each mode [m x 1].
    [[nodiscard]] Eigen::VectorXcd project(const Eigen::VectorXd& row) const;
    // Modal coordinates c = L x of the representatives (the conjugate modes get conj(c)).
    [[nodiscard]] Eigen::VectorXcd coordinates(const Eigen::VectorXd& x) const;
    // L x for a complex x (particular solutions, checks); the conjugate rows are conj(L).
    [[nodiscard]] Eigen::VectorXcd coordinates(const Eigen::VectorXcd& x) const;
    // x = sum over all 2n modes of R_k c_k for a real state whose representatives' coordinates are c.
    [[nodiscard]] Eigen::VectorXd state(const Eigen::VectorXcd& c) const;
    // v_k as a dense vector, and the left row of mode k.
    [[nodiscard]] Eigen::VectorXcd right(int k) const;
    [[nodiscard]] Eigen::RowVectorXcd left(int k) const;
};

// Every mode written out: 2n eigenvalues [lambda; conj(lambda of paired)], R (2n x 2n columns) and
// L (2n x 2n rows) with L R = I. For the energy ledger's quadratic forms and for tests.
struct FullModes {
    Eigen::VectorXcd lambda;
    Eigen::MatrixXcd R;
    Eigen::MatrixXcd L;
};
FullModes expand(const StateModes& s);

// The system matrix A of a contact set in x coordinates (dense, 2n x 2n): for tests and fallback.
Eigen::MatrixXd state_matrix(const BaseModes& b, const PiecewiseLinearProblem& p, const std::vector<bool>& active);

// Decomposes the contact set: closed form for no contact, a secular-equation (Aberth) solution of
// the rank-one update for one contact, a dense eigen solve otherwise or when the fast path cannot
// verify itself. Throws NotDiagonalisable when even the dense path is not diagonalisable.
StateModes decompose_state(const BaseModes& b, const PiecewiseLinearProblem& p, const std::vector<bool>& active);

}  // namespace vi
