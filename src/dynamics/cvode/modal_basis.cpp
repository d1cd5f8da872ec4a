#include "dynamics/cvode/modal_basis.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "modal/eigen_solver.hpp"

namespace vi {

namespace {

// Every mode of (K, M) with K only semi-definite (a body free to move, held by its contacts alone:
// the closed-form checks of one free mass): the standard problem L^-1 K L^-T with M = L L^T. Less
// accurate for the lowest modes of a stiff beam than the inverse form all_modes_dense uses, so only
// the fallback; eigenvalues negative by roundoff are rigid-body modes (0).
ModeSet all_modes_semidefinite(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M) {
    const Eigen::MatrixXd Md(M), Kd(K);
    const Eigen::LLT<Eigen::MatrixXd> llt(Md);
    if (llt.info() != Eigen::Success) throw std::runtime_error("modal basis: the mass matrix is not positive definite");
    const Eigen::MatrixXd Linv = llt.matrixL().solve(Eigen::MatrixXd::Identity(Md.rows(), Md.cols()));
    const Eigen::MatrixXd A = Linv * Kd * Linv.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (A + A.transpose()));
    if (es.info() != Eigen::Success) throw std::runtime_error("modal basis: the eigen solve failed");
    ModeSet set;
    set.omega = es.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    set.shapes = Linv.transpose() * es.eigenvectors();
    return set;
}

}  // namespace

ModalBasis full_basis(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M) {
    ModeSet set;
    try {
        set = all_modes_dense(K, M);
    } catch (const std::runtime_error&) {
        set = all_modes_semidefinite(K, M);
    }
    ModalBasis b;
    b.phi = set.shapes;
    b.omega = set.omega;
    b.modes = static_cast<int>(set.omega.size());
    b.full = true;
    return b;
}

ModalBasis nodal_basis(int n) {
    ModalBasis b;
    b.modes = n;
    b.full = true;
    b.nodal = true;
    b.dofs = n;
    return b;
}

ModalBasis reduced_basis(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, int modes,
                         const std::vector<Eigen::VectorXd>& loads, const std::vector<Eigen::VectorXd>& extra) {
    const Eigen::Index n = K.rows();
    if (modes >= n) return full_basis(K, M);
    const ModeSet set = lowest_modes(K, M, modes);
    std::vector<Eigen::VectorXd> candidates;
    for (int k = 0; k < set.omega.size(); ++k) candidates.emplace_back(set.shapes.col(k));
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(K);
    if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 0.0).all()) {
        throw std::runtime_error("reduced basis: the beam is free to move as a rigid body (its static corrections do "
                                 "not exist); use solver.reduced_modes = 0");
    }
    for (const Eigen::VectorXd& f : loads) {
        if (f.size() == n && f.squaredNorm() > 0.0) candidates.emplace_back(ldlt.solve(f));
    }
    for (const Eigen::VectorXd& x : extra) {
        if (x.size() == n && x.squaredNorm() > 0.0) candidates.push_back(x);
    }
    // M-orthonormalise (modified Gram-Schmidt, twice), dropping what the set already spans.
    std::vector<Eigen::VectorXd> basis;
    for (Eigen::VectorXd v : candidates) {
        const double size0 = std::sqrt(v.dot(M * v));
        if (!(size0 > 0.0)) continue;
        for (int pass = 0; pass < 2; ++pass) {
            for (const Eigen::VectorXd& u : basis) v -= u * u.dot(M * v);
        }
        const double size = std::sqrt(v.dot(M * v));
        if (!(size > 1e-10 * size0)) continue;
        basis.push_back(v / size);
    }
    const Eigen::Index r = static_cast<Eigen::Index>(basis.size());
    Eigen::MatrixXd psi(n, r);
    for (Eigen::Index k = 0; k < r; ++k) psi.col(k) = basis[static_cast<std::size_t>(k)];
    const Eigen::MatrixXd kr = psi.transpose() * (K * psi);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (kr + kr.transpose()));
    if (es.info() != Eigen::Success || !(es.eigenvalues().minCoeff() > 0.0)) {
        throw std::runtime_error("reduced basis: the Ritz stiffness is not positive definite");
    }
    ModalBasis b;
    b.phi = psi * es.eigenvectors();
    b.omega = es.eigenvalues().cwiseSqrt();
    b.modes = static_cast<int>(set.omega.size());
    b.full = false;
    return b;
}

}  // namespace vi
