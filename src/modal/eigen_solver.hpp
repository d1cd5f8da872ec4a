#pragma once
// Generalised symmetric eigenproblem K phi = omega^2 M phi: lowest modes, mass normalised.

#include <Eigen/Dense>

#include "fem/system.hpp"

namespace vi {

// Circular frequencies (ascending) [rad/s] and mass-normalised shapes (columns, phi^T M phi = 1).
struct ModeSet {
    Eigen::VectorXd omega;
    Eigen::MatrixXd shapes;
};

// Problems up to this size are solved densely (all modes, LAPACK-free Eigen); larger ones by
// Spectra's shift-invert Lanczos for the requested count only.
inline constexpr int kDenseEigenLimit = 200;

// The lowest count modes of (K, M); count is clipped to the problem size. Throws
// std::runtime_error when the solver does not converge or K is not positive definite.
ModeSet lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int count);

// The lowest count circular frequencies [rad/s] of (K, M) alone, as lowest_modes gives them, for a
// caller that needs no shapes (the frequencies under bias of `pullin`).
Eigen::VectorXd lowest_frequencies(const SparseMatrix& K, const SparseMatrix& M, int count);

// Every mode of (K, M) by a dense solver, whatever the size.
ModeSet all_modes_dense(const SparseMatrix& K, const SparseMatrix& M);

// Every circular frequency of (K, M) [rad/s], ascending, by the same dense solver without the
// shapes: the same numbers as all_modes_dense(K, M).omega at about half its cost.
Eigen::VectorXd all_frequencies_dense(const SparseMatrix& K, const SparseMatrix& M);

// Every mode wanted by count through Spectra, whatever the size (cross-check of the dense path).
ModeSet lowest_modes_sparse(const SparseMatrix& K, const SparseMatrix& M, int count);

}  // namespace vi
