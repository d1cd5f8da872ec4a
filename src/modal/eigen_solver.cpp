#include "modal/eigen_solver.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/run_control.hpp"

namespace vi {
namespace {

// Spectra's shift-invert operator with a stop check (model/run_control.hpp) on every product: a
// Lanczos iteration on a fine mesh runs for seconds, and a signal must stop it within milliseconds.
class CheckedShiftInvert : public Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse> {
public:
    using Base = Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse>;
    using Base::Base;
    void perform_op(const double* x_in, double* y_out) const {
        check_run();
        Base::perform_op(x_in, y_out);
    }
};

// Enforces phi^T M phi = 1 exactly and a reproducible sign: the largest component positive.
void normalise_column(Eigen::Ref<Eigen::VectorXd> col, const SparseMatrix& M) {
    const double mm = col.dot(M * col);
    col /= std::sqrt(mm);
    Eigen::Index imax = 0;
    col.cwiseAbs().maxCoeff(&imax);
    if (col[imax] < 0) col = -col;
}

void normalise(ModeSet& set, const SparseMatrix& M) {
    for (Eigen::Index j = 0; j < set.shapes.cols(); ++j) normalise_column(set.shapes.col(j), M);
}

ModeSet from_eigenvalues(const Eigen::VectorXd& lambda, Eigen::MatrixXd shapes) {
    if (lambda.size() > 0 && !(lambda.minCoeff() > 0.0)) {
        throw std::runtime_error("eigen solve: stiffness is not positive definite (a rigid-body mode remains)");
    }
    ModeSet set;
    set.omega = lambda.cwiseSqrt();
    set.shapes = std::move(shapes);
    return set;
}


// Symmetric diagonal scaling D K D with unit diagonal: v rows (EI/L^3) and theta rows (EI/L) differ
// by L^-2, many decades for a fine mesh, which would otherwise spoil the factorisations.
Eigen::VectorXd equilibration(const SparseMatrix& K) {
    Eigen::VectorXd d = K.diagonal();
    if (!(d.minCoeff() > 0.0)) {
        throw std::runtime_error("eigen solve: stiffness is not positive definite (a rigid-body mode remains)");
    }
    return d.cwiseSqrt().cwiseInverse();
}

// The dense solution of (K, M): the frequencies, and what forms any shape on its own (the
// equilibration, the factor of K and the reduced problem's eigenvectors), so that a caller that
// wants the lowest few shapes forms only those, each exactly as when all are formed.
struct DenseSolution {
    Eigen::VectorXd omega;
    Eigen::VectorXd d;
    Eigen::MatrixXd factor;   // K's scaled Cholesky factor L in the lower triangle (Eigen's LLT storage)
    Eigen::MatrixXd vectors;  // of the reduced problem, ascending 1/omega^2; empty for the frequencies alone
};

// With shapes = false, only the circular frequencies: the eigenvector accumulation and the
// back-substitution are about half of the dense solution's cost.
DenseSolution solve_dense(const SparseMatrix& K, const SparseMatrix& M, bool shapes) {
    // Solved as the inverse problem (L^-1 M L^-T) y = (1/omega^2) y with K = L L^T: the lowest modes,
    // the ones that matter, then carry the largest eigenvalues and hence full relative accuracy.
    // A stop is honoured between the stages (each one Eigen call, O(n^3): 0.1 s at n = 400).
    check_run();
    DenseSolution sol;
    sol.d = equilibration(K);
    const Eigen::VectorXd& d = sol.d;
    const Eigen::MatrixXd ks = d.asDiagonal() * Eigen::MatrixXd(K) * d.asDiagonal();
    const Eigen::MatrixXd ms = d.asDiagonal() * Eigen::MatrixXd(M) * d.asDiagonal();
    const Eigen::LLT<Eigen::MatrixXd> llt(ks);
    if (llt.info() != Eigen::Success) {
        throw std::runtime_error("eigen solve: stiffness is not positive definite (a rigid-body mode remains)");
    }
    check_run();
    Eigen::MatrixXd c = llt.matrixL().solve(ms);
    c = llt.matrixL().solve(c.transpose()).transpose();
    check_run();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (c + c.transpose()),
                                                      shapes ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
    if (es.info() != Eigen::Success) throw std::runtime_error("eigen solve: dense solver failed");
    check_run();
    const Eigen::Index n = c.rows();
    Eigen::VectorXd lambda(n);
    for (Eigen::Index j = 0; j < n; ++j) lambda[j] = 1.0 / es.eigenvalues()[n - 1 - j];  // descending 1/omega^2 = ascending omega
    sol.omega = from_eigenvalues(lambda, Eigen::MatrixXd()).omega;
    if (shapes) {
        sol.vectors = es.eigenvectors();
        sol.factor = llt.matrixLLT();
    }
    return sol;
}

// Shape j (ascending omega) of a dense solution, mass normalised.
Eigen::VectorXd dense_shape(const DenseSolution& sol, const SparseMatrix& M, Eigen::Index j) {
    const Eigen::Index src = sol.vectors.cols() - 1 - j;
    // L^T x = y, as LLT::matrixU() solves it.
    Eigen::VectorXd col = sol.d.asDiagonal() * sol.factor.adjoint().triangularView<Eigen::Upper>().solve(sol.vectors.col(src));
    normalise_column(col, M);
    return col;
}

// Whether a kept dense matrix holds exactly the entries of a sparse one.
bool same_matrix(const Eigen::MatrixXd& dense, const SparseMatrix& sparse) {
    if (dense.rows() != sparse.rows() || dense.cols() != sparse.cols()) return false;
    return dense == Eigen::MatrixXd(sparse);
}

// The last dense solution on this thread, kept with the matrices it belongs to: a transient
// computes the modes of the same (K, M) twice (the problem's frequencies and the solver's basis),
// and the points of a sweep that keep the mesh and the material (contact stiffness, damping, gap,
// initial step) share them. A different (K, M) replaces it; the result is the same either way.
struct DenseModesMemo {
    Eigen::MatrixXd K, M;
    DenseSolution solution;  // its factors are dropped once every shape is formed
    ModeSet modes;           // the shapes formed so far: the first `formed` columns
    Eigen::Index formed = 0;

    // The solution of (K, M) with its first `count` shapes formed.
    const ModeSet& at_least(const SparseMatrix& k, const SparseMatrix& m, Eigen::Index count) {
        if (!(same_matrix(K, k) && same_matrix(M, m))) {
            DenseSolution sol = solve_dense(k, m, true);
            K = Eigen::MatrixXd(k);
            M = Eigen::MatrixXd(m);
            const Eigen::Index n = sol.omega.size();
            modes.omega = sol.omega;
            modes.shapes.resize(n, n);
            solution = std::move(sol);
            formed = 0;
        }
        const Eigen::Index n = modes.omega.size();
        count = std::min(count, n);
        for (; formed < count; ++formed) modes.shapes.col(formed) = dense_shape(solution, m, formed);
        if (formed == n) {
            solution.vectors.resize(0, 0);
            solution.factor.resize(0, 0);
        }
        return modes;
    }
};

DenseModesMemo& dense_memo() {
    thread_local DenseModesMemo memo;
    return memo;
}

// The size of the Lanczos basis Spectra builds for count modes (before clipping to the problem).
int lanczos_basis_size(int count) { return std::max(2 * count + 1, count + 20); }

}  // namespace

ModeSet all_modes_dense(const SparseMatrix& K, const SparseMatrix& M) { return dense_memo().at_least(K, M, K.rows()); }

Eigen::VectorXd all_frequencies_dense(const SparseMatrix& K, const SparseMatrix& M) { return solve_dense(K, M, false).omega; }

ModeSet lowest_modes_sparse(const SparseMatrix& K, const SparseMatrix& M, int count) {
    const int n = static_cast<int>(K.rows());
    const int nev = std::clamp(count, 1, std::max(1, n - 1));
    const int ncv = std::min(n, lanczos_basis_size(nev));
    const Eigen::VectorXd d = equilibration(K);
    const SparseMatrix ks = d.asDiagonal() * K * d.asDiagonal();
    // Spectra judges convergence against max(|ritz value|, eps^(2/3)); scaling M to a unit largest
    // diagonal makes the ritz values 1/lambda large, so the relative test applies.
    const SparseMatrix ms0 = d.asDiagonal() * M * d.asDiagonal();
    const double mscale = ms0.diagonal().maxCoeff();
    const SparseMatrix ms = ms0 / mscale;
    check_run();
    using OpType = CheckedShiftInvert;
    using BOpType = Spectra::SparseSymMatProd<double>;
    OpType op(ks, ms);
    BOpType bop(ms);
    Spectra::SymGEigsShiftSolver<OpType, BOpType, Spectra::GEigsMode::ShiftInvert> solver(op, bop, nev, ncv, 0.0);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-13, Spectra::SortRule::SmallestAlge);
    if (solver.info() != Spectra::CompInfo::Successful) {
        throw std::runtime_error("eigen solve: Lanczos iteration did not converge");
    }
    ModeSet set = from_eigenvalues(solver.eigenvalues() / mscale, d.asDiagonal() * solver.eigenvectors());
    normalise(set, M);
    return set;
}

ModeSet lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int count) {
    const int n = static_cast<int>(K.rows());
    if (n == 0) return {};
    count = std::clamp(count, 0, n);
    if (n <= kDenseEigenLimit || count >= n - 1) {
        // Only the shapes asked for are formed (the rest when a later call on the same matrices wants them).
        const ModeSet& all = dense_memo().at_least(K, M, count);
        return {all.omega.head(count), all.shapes.leftCols(count)};
    }
    return lowest_modes_sparse(K, M, count);
}

Eigen::VectorXd lowest_frequencies(const SparseMatrix& K, const SparseMatrix& M, int count) {
    const int n = static_cast<int>(K.rows());
    if (n == 0) return {};
    count = std::clamp(count, 0, n);
    // Lanczos builds its basis at one sparse solve a vector: for a few modes of a problem several
    // times the basis' size it does less work than the dense solution of all n (at n = 100 and 3
    // modes, half of it by callgrind).
    if (count >= n - 1 || n < 3 * lanczos_basis_size(count)) {
        return solve_dense(K, M, false).omega.head(count);
    }
    return lowest_modes_sparse(K, M, count).omega;
}

}  // namespace vi
