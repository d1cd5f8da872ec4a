#pragma once
// ModalBasis: the coordinates the nonlinear (CVODE) path integrates in. Mass-normalised vectors that
// diagonalise the beam's M and K, so the linear part (with Rayleigh damping) is diagonal and no mass
// matrix is ever inverted; force elements act on the few DOFs they name through rows of the basis.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

namespace vi {

// q = phi eta, with phi^T M phi = I and phi^T K phi = diag(omega^2); or, `nodal`, the FE DOFs
// themselves (phi = I, not stored; eta = q, and M, K are not diagonal in it).
struct ModalBasis {
    Eigen::MatrixXd phi;        // n x r [1/sqrt(kg)]; empty when nodal
    Eigen::VectorXd omega;      // r circular frequencies, ascending [rad/s]; empty when nodal
    int modes = 0;              // how many columns are modes of the beam (the rest: static corrections)
    bool full = true;           // every mode of (K, M): the change of coordinates is exact
    bool nodal = false;         // the state is in the FE DOFs (docs/model.md §13)
    int dofs = 0;               // n, when nodal
    [[nodiscard]] int size() const { return nodal ? dofs : static_cast<int>(omega.size()); }
};

// The FE DOFs as the coordinates of a full model of n DOFs.
ModalBasis nodal_basis(int n);

// Every bending mode: the full FE model in modal coordinates (a dense eigen solve, O(n^3)).
ModalBasis full_basis(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M);

// A reduced-order basis: the lowest `modes` modes, augmented by the static response K^-1 f to each
// load in `loads` (the force elements' load patterns) and by the vectors in `extra`
// (the initial displacement and velocity, so that the start is represented exactly). The set is
// made M-orthonormal and diagonalised in its span (a Rayleigh-Ritz solve), so it is again a set of
// frequencies and vectors: the `modes` lowest are the beam's own, the static corrections become high
// Ritz frequencies (modal truncation augmentation; docs/model.md §13). Vectors that the others
// already span (to 1e-10) are dropped.
ModalBasis reduced_basis(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, int modes,
                         const std::vector<Eigen::VectorXd>& loads, const std::vector<Eigen::VectorXd>& extra);

}  // namespace vi
