#pragma once
// The Newton matrix of a full modal basis solved in the beam's own DOFs. In modal coordinates a
// distributed force (an electrode, a film) makes the matrix a dense r x r one; in the FE DOFs the
// same matrix is the sparse b^2 M + a^2 K - a b C plus the elements' banded tangents, factorised in
// O(n) and solved with two passes over phi (phi^-T = M phi for phi^T M phi = I). Internal to the
// CVODE solver (dynamics/cvode/cvode_linear_solver.*). On a nodal basis (the state in the FE DOFs)
// the same factorisation is the whole Newton solve, with no pass over a basis.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <vector>

#include "dynamics/cvode/cvode_system.hpp"

namespace vi::cvode_detail {

class PhysicalNewton {
public:
    // Only for a full basis (square phi) or a nodal one.
    explicit PhysicalNewton(const ModalSystem& system);

    // The elements' summed tangents Fq = sum d f / d q, Fv = sum d f / d v on the DOFs `dofs` (one
    // FE DOF index per row of Fq and Fv; dense s x s, banded in content).
    void set_tangents(const Eigen::MatrixXd& Fq, const Eigen::MatrixXd& Fv, const std::vector<int>& dofs);
    // The same, already on the FE DOFs (n x n).
    void set_tangents(Eigen::SparseMatrix<double> Eq, Eigen::SparseMatrix<double> Ev);
    // Factorises b^2 M + a^2 K - a b C - a^2 Fq + a b Fv; false when it is singular.
    [[nodiscard]] bool factor(double a, double b);
    // x_v of the modal Newton system (Delta + P^T W P) x_v = b r_v + a w^2 r_eta - a P^T Fq P r_eta
    // (cvode_linear_solver.cpp), with the a and b of the last factor().
    void solve(const Eigen::Ref<const Eigen::VectorXd>& r_eta, const Eigen::Ref<const Eigen::VectorXd>& r_v,
               Eigen::VectorXd& xv);
    // x_v of the nodal Newton system: (b I + a J) x = r with J the Jacobian of q' = v,
    // v' = M^-1 (f - K q - C v), x_q eliminated: A x_v = b M r_v + a K r_q - a Fq r_q.
    void solve_nodal(const Eigen::Ref<const Eigen::VectorXd>& r_q, const Eigen::Ref<const Eigen::VectorXd>& r_v,
                     Eigen::VectorXd& xv);

private:
    const ModalSystem& sys_;
    Eigen::SparseMatrix<double> M_, K_;        // the beam's mass and stiffness (bending DOFs)
    Eigen::SparseMatrix<double> Eq_, Ev_;      // the tangents on the FE DOFs (n x n, sparse)
    Eigen::SparseMatrix<double> A_;            // the matrix scaled to a unit diagonal: S A S
    Eigen::VectorXd scale_;                    // S = 1 / sqrt|diag A|
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
    bool pattern_ = false;                     // lu_ holds the pattern of A_
    double a_ = 0.0, b_ = 1.0;
    Eigen::MatrixXd cols_, phys_;              // the solve's two modal vectors and their images
    Eigen::VectorXd g_, z_;
};

}  // namespace vi::cvode_detail
