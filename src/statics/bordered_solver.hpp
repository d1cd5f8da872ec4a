#pragma once
// The bordered linear system [A b; c^T 0] [x; y] = [f; g] of a continuation step, A symmetric and
// sparse: Newton's matrix of `pullin`, with y the squared voltage [dimensionless solver].

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include "fem/system.hpp"

namespace vi {

// Solves by block elimination on A's sparse LDL^T with one step of iterative refinement, which is
// accurate even as A turns singular at a fold (Govaerts & Pryce 1990); the LDL^T keeps its symbolic
// analysis while A's pattern stays the same. When that LDL^T does not exist or the refined residual
// is not small (A singular or not symmetric), the whole bordered matrix is solved by sparse LU.
class BorderedSolver {
public:
    // Takes A, b and c (kept until the next call); false when the bordered matrix is singular.
    bool factorize(SparseMatrix a, Eigen::VectorXd b, Eigen::VectorXd c);

    // The solution for the last factorised system; false when it is not finite.
    bool solve(const Eigen::VectorXd& f, double g, Eigen::VectorXd& x, double& y);

    // Whether a symmetric A is positive definite: its LDL^T exists with every pivot positive (by
    // Sylvester's law of inertia). Factorises A alone: solve() then needs a new factorize().
    bool positive_definite(const SparseMatrix& a);

    // How many factorisations or solves fell back to the sparse LU (for tests and benchmarks).
    int fallbacks() const { return fallbacks_; }

private:
    bool factorize_ldlt(const SparseMatrix& a);
    bool factorize_lu();
    bool solve_by_elimination(const Eigen::VectorXd& f, double g, Eigen::VectorXd& x, double& y) const;
    bool residual_small(const Eigen::VectorXd& f, double g, const Eigen::VectorXd& x, double y) const;
    bool solve_by_lu(const Eigen::VectorXd& f, double g, Eigen::VectorXd& x, double& y);

    SparseMatrix a_;
    Eigen::VectorXd b_, c_, v_;  // v = A^-1 b
    bool ready_ = false;         // a system is factorised
    double delta_ = 0.0;         // the Schur complement -c^T A^-1 b
    double a_norm_ = 0.0;        // |A| (infinity norm)
    bool ldlt_ok_ = false;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
    Eigen::VectorXi outer_, inner_;  // the pattern ldlt_ was analysed for
    bool analysed_ = false;
    bool lu_ready_ = false;
    Eigen::SparseLU<SparseMatrix> lu_;
    int fallbacks_ = 0;
};

}  // namespace vi
