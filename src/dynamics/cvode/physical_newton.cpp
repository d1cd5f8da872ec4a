#include "dynamics/cvode/physical_newton.hpp"

#include "dynamics/cvode/dual_product.hpp"

#include <utility>
#include <vector>

namespace vi::cvode_detail {

namespace {

// The nonzero entries of the s x s block F placed on the FE DOFs `dofs` of an n x n matrix.
Eigen::SparseMatrix<double> spread(const Eigen::MatrixXd& F, const std::vector<int>& dofs, Eigen::Index n) {
    std::vector<Eigen::Triplet<double>> t;
    for (Eigen::Index j = 0; j < F.cols(); ++j)
        for (Eigen::Index i = 0; i < F.rows(); ++i)
            if (F(i, j) != 0.0) t.emplace_back(dofs[static_cast<std::size_t>(i)], dofs[static_cast<std::size_t>(j)], F(i, j));
    Eigen::SparseMatrix<double> out(n, n);
    out.setFromTriplets(t.begin(), t.end());
    return out;
}

}  // namespace

PhysicalNewton::PhysicalNewton(const ModalSystem& system)
    : sys_(system), M_(system.problem().M), K_(system.problem().K) {
    Eq_.resize(M_.rows(), M_.cols());
    Ev_.resize(M_.rows(), M_.cols());
}

void PhysicalNewton::set_tangents(const Eigen::MatrixXd& Fq, const Eigen::MatrixXd& Fv, const std::vector<int>& dofs) {
    const Eigen::Index n = M_.rows();
    Eq_ = spread(Fq, dofs, n);
    Ev_ = spread(Fv, dofs, n);
    pattern_ = false;
}

void PhysicalNewton::set_tangents(Eigen::SparseMatrix<double> Eq, Eigen::SparseMatrix<double> Ev) {
    Eq_ = std::move(Eq);
    Ev_ = std::move(Ev);
    pattern_ = false;
}

bool PhysicalNewton::factor(double a, double b) {
    a_ = a;
    b_ = b;
    const TransientProblem& p = sys_.problem();
    // Delta = b^2 + a^2 w^2 - a b (alpha + beta w^2) per mode is phi^T (b^2 M + a^2 K - a b C) phi.
    const double cm = b * b - a * b * p.alpha, ck = a * a - a * b * p.beta;
    A_ = cm * M_ + ck * K_ - (a * a) * Eq_ + (a * b) * Ev_;
    // Displacements and rotations differ in scale by the element length squared (1e-11 at m = 20
    // on the paper's beam): without a symmetric scaling to a unit diagonal the LU's pivots mix them
    // and its solutions lose every digit at large steps.
    scale_ = A_.diagonal().cwiseAbs().cwiseSqrt().cwiseInverse();
    if (!scale_.allFinite()) return false;
    A_ = scale_.asDiagonal() * A_ * scale_.asDiagonal();
    A_.makeCompressed();
    if (!pattern_) {
        lu_.analyzePattern(A_);
        pattern_ = true;
    }
    lu_.factorize(A_);
    return lu_.info() == Eigen::Success;
}

// (phi^T A phi) x_v = t gives A (phi x_v) = phi^-T t = M phi t, and x_v = phi^-1 z = phi^T M z. The
// tangent term of t enters as M phi P^T Fq P r_eta = Eq phi r_eta (phi phi^T = M^-1). The two
// products by phi share one pass over it (two columns): with the one by phi^T they are the solve's
// O(n^2) part, the rest is sparse.
void PhysicalNewton::solve(const Eigen::Ref<const Eigen::VectorXd>& r_eta, const Eigen::Ref<const Eigen::VectorXd>& r_v,
                           Eigen::VectorXd& xv) {
    const Eigen::VectorXd& w = sys_.basis().omega;
    const Eigen::Index r = r_eta.size();
    cols_.resize(r, 2);
    cols_.col(0) = b_ * r_v + a_ * w.cwiseAbs2().cwiseProduct(r_eta);
    cols_.col(1) = r_eta;
    phys_.resize(sys_.basis().phi.rows(), 2);
    dual_product(sys_.basis().phi, cols_.col(0).data(), cols_.col(1).data(), phys_.col(0), phys_.col(1));
    g_.noalias() = M_ * phys_.col(0);
    if (Eq_.nonZeros() > 0) g_.noalias() -= a_ * (Eq_ * phys_.col(1));
    g_.array() *= scale_.array();
    z_ = lu_.solve(g_);
    z_.array() *= scale_.array();
    g_.noalias() = M_ * z_;
    xv.noalias() = sys_.basis().phi.transpose() * g_;
}

// Row 2 of (b I + a J) x = r times M: b M x_v + a (Fq - K) x_q + a (Fv - C) x_v = M r_v; with
// x_q = (r_q - a x_v) / b and times b it is A x_v = b M r_v + a (K - Fq) r_q.
void PhysicalNewton::solve_nodal(const Eigen::Ref<const Eigen::VectorXd>& r_q, const Eigen::Ref<const Eigen::VectorXd>& r_v,
                                 Eigen::VectorXd& xv) {
    g_.noalias() = b_ * (M_ * r_v);
    g_.noalias() += a_ * (K_ * r_q);
    if (Eq_.nonZeros() > 0) g_.noalias() -= a_ * (Eq_ * r_q);
    g_.array() *= scale_.array();
    xv = lu_.solve(g_);
    xv.array() *= scale_.array();
}

}  // namespace vi::cvode_detail
