#include "dynamics/cvode/nodal_linear_part.hpp"

#include <cmath>
#include <stdexcept>

namespace vi::cvode_detail {

namespace {

bool positive_definite(const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& f) {
    return f.info() == Eigen::Success && (f.vectorD().array() > 0.0).all();
}

}  // namespace

NodalLinearPart::NodalLinearPart(const Eigen::SparseMatrix<double>& M, const Eigen::SparseMatrix<double>& K,
                                 double alpha, double beta)
    : M_(M), K_(K), alpha_(alpha), beta_(beta) {
    M_.makeCompressed();
    K_.makeCompressed();
    mass_.compute(M_);
    if (!positive_definite(mass_)) throw std::runtime_error("nodal state: the mass matrix is not positive definite");
    stiff_.compute(K_);
    if (!positive_definite(stiff_)) throw std::runtime_error("nodal state: the stiffness matrix is not positive definite");
    kv_.resize(M_.rows());
    mv_.resize(M_.rows());
}

double NodalLinearPart::linear_force(const double* q, const double* v, double* out) const {
    using ConstVec = Eigen::Map<const Eigen::VectorXd>;
    const Eigen::Index n = M_.rows();
    const ConstVec vv(v, n);
    kv_.noalias() = K_ * vv;
    mv_.noalias() = M_ * vv;
    // C v, then the Rayleigh power before K q is added.
    Eigen::Map<Eigen::VectorXd> f(out, n);
    f = alpha_ * mv_ + beta_ * kv_;
    const double power = vv.dot(f);
    // K q cancels to the load it balances, (l/h)^4 ~ m^4 smaller than its terms: summed in double
    // its roundoff is a noise of about 1e-16 m^4 in the accelerations, which CVODE's error test meets
    // on fine meshes at tight tolerances (the switch example at m = 200 and rtol 1e-10 took five
    // times the steps of m = 100). Summed in long double (64-bit mantissa) it is 2000 times less.
    acc_.assign(static_cast<std::size_t>(n), 0.0L);
    const double* values = K_.valuePtr();
    const int* inner = K_.innerIndexPtr();
    const int* outer = K_.outerIndexPtr();
    for (Eigen::Index j = 0; j < n; ++j) {
        const long double qj = q[j];
        for (int k = outer[j]; k < outer[j + 1]; ++k) acc_[static_cast<std::size_t>(inner[k])] += values[k] * qj;
    }
    for (Eigen::Index i = 0; i < n; ++i) f[i] = -static_cast<double>(acc_[static_cast<std::size_t>(i)] + f[i]);
    return power;
}

void NodalLinearPart::solve_mass(double* f) const {
    Eigen::Map<Eigen::VectorXd> x(f, M_.rows());
    tmp_ = mass_.solve(x);
    x = tmp_;
}

double NodalLinearPart::kinetic(const double* v) const {
    const Eigen::Map<const Eigen::VectorXd> vv(v, M_.rows());
    return 0.5 * vv.dot(M_ * vv);
}

double NodalLinearPart::strain(const double* q) const {
    const Eigen::Map<const Eigen::VectorXd> qv(q, K_.rows());
    return 0.5 * qv.dot(K_ * qv);
}

double NodalLinearPart::flexibility(int i) const {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(K_.rows());
    e[i] = 1.0;
    return stiff_.solve(e)[i];
}

double NodalLinearPart::top_frequency() const {
    if (top_ > 0.0) return top_;
    // Power iteration on M^-1 K from an alternating vector (rich in the highest modes); the Rayleigh
    // quotient converges as the square of the vector's error. Bounded: 200 iterations at most.
    const Eigen::Index n = M_.rows();
    Eigen::VectorXd x(n);
    for (Eigen::Index i = 0; i < n; ++i) x[i] = (i % 4 < 2) ? 1.0 : -1.0;
    double lambda = 0.0;
    for (int it = 0; it < 200; ++it) {
        const Eigen::VectorXd kx = K_ * x;
        const double next = x.dot(kx) / x.dot(M_ * x);
        x = mass_.solve(kx);
        x /= x.norm();
        const bool settled = it > 10 && std::abs(next - lambda) <= 1e-4 * next;
        lambda = next;
        if (settled) break;
    }
    top_ = std::sqrt(std::max(lambda, 0.0));
    return top_;
}

}  // namespace vi::cvode_detail
