#pragma once
// NodalLinearPart: the beam's linear part in its own FE DOFs, for a CVODE state that holds q and v
// themselves (a full model integrated without a modal basis; docs/model.md §13). M a = f - K q - C v
// is solved through a sparse LDL^T of the banded M, factorised once, so a right-hand side costs O(n)
// where the modal basis's dense rows cost O(n^2). Internal to the CVODE solver.

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

namespace vi::cvode_detail {

class NodalLinearPart {
public:
    // M and K over the bending DOFs, C = alpha M + beta K. Throws std::runtime_error when M or K is
    // not positive definite (a body held by its contacts alone has no static flexibility to scale
    // its tolerances by; the modal basis takes it).
    NodalLinearPart(const Eigen::SparseMatrix<double>& M, const Eigen::SparseMatrix<double>& K, double alpha,
                    double beta);

    [[nodiscard]] int size() const { return static_cast<int>(M_.rows()); }
    [[nodiscard]] const Eigen::SparseMatrix<double>& mass() const { return M_; }
    [[nodiscard]] const Eigen::SparseMatrix<double>& stiffness() const { return K_; }

    // out = -(K q + C v); returns the Rayleigh power v^T C v [W].
    double linear_force(const double* q, const double* v, double* out) const;
    // f = M^-1 f in place.
    void solve_mass(double* f) const;
    [[nodiscard]] double kinetic(const double* v) const;  // 1/2 v^T M v [J]
    [[nodiscard]] double strain(const double* q) const;   // 1/2 q^T K q [J]
    // (K^-1)_ii: the static flexibility of DOF i [m/N, rad/(N m)].
    [[nodiscard]] double flexibility(int i) const;
    // The highest circular frequency of (K, M) [rad/s], by power iteration on M^-1 K (to about 1e-3;
    // for the undamped-top check and its message), computed on the first call.
    [[nodiscard]] double top_frequency() const;

private:
    Eigen::SparseMatrix<double> M_, K_;
    double alpha_ = 0.0, beta_ = 0.0;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> mass_, stiff_;
    mutable double top_ = 0.0;
    mutable Eigen::VectorXd kv_, mv_, tmp_;
    mutable std::vector<long double> acc_;
};

}  // namespace vi::cvode_detail
