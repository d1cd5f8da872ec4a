#include "statics/bordered_solver.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace vi {

namespace {

// The refined residual must be this small against |A| |x| + |b| |y| + |f| (norm-wise backward
// error): far above roundoff (n eps with n in the hundreds), far below Newton's 1e-9 tolerance.
constexpr double kResidualTolerance = 1e-11;

bool same_pattern(const SparseMatrix& a, const Eigen::VectorXi& outer, const Eigen::VectorXi& inner) {
    if (outer.size() != a.outerSize() + 1 || inner.size() != a.nonZeros()) return false;
    return std::equal(outer.begin(), outer.end(), a.outerIndexPtr()) &&
           std::equal(inner.begin(), inner.end(), a.innerIndexPtr());
}

}  // namespace

bool BorderedSolver::factorize_ldlt(const SparseMatrix& a) {
    if (!a.isCompressed()) return false;
    if (!analysed_ || !same_pattern(a, outer_, inner_)) {
        ldlt_.analyzePattern(a);
        outer_ = Eigen::Map<const Eigen::VectorXi>(a.outerIndexPtr(), a.outerSize() + 1);
        inner_ = Eigen::Map<const Eigen::VectorXi>(a.innerIndexPtr(), a.nonZeros());
        analysed_ = true;
    }
    ldlt_.factorize(a);
    return ldlt_.info() == Eigen::Success;
}

bool BorderedSolver::factorize_lu() {
    const Eigen::Index n = a_.rows();
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(a_.nonZeros() + 2 * n));
    for (Eigen::Index k = 0; k < a_.outerSize(); ++k) {
        for (SparseMatrix::InnerIterator it(a_, k); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
    }
    for (Eigen::Index i = 0; i < n; ++i) {
        if (b_[i] != 0.0) t.emplace_back(i, n, b_[i]);
        if (c_[i] != 0.0) t.emplace_back(n, i, c_[i]);
    }
    SparseMatrix j(n + 1, n + 1);
    j.setFromTriplets(t.begin(), t.end());
    lu_.compute(j);
    lu_ready_ = lu_.info() == Eigen::Success;
    return lu_ready_;
}

bool BorderedSolver::factorize(SparseMatrix a, Eigen::VectorXd b, Eigen::VectorXd c) {
    a_ = std::move(a);
    b_ = std::move(b);
    c_ = std::move(c);
    lu_ready_ = false;
    ready_ = true;
    a_norm_ = (a_.cwiseAbs() * Eigen::VectorXd::Ones(a_.cols())).lpNorm<Eigen::Infinity>();
    ldlt_ok_ = factorize_ldlt(a_);
    if (ldlt_ok_) {
        v_ = ldlt_.solve(b_);
        delta_ = -c_.dot(v_);
        ldlt_ok_ = v_.allFinite() && std::isfinite(delta_) && delta_ != 0.0;
    }
    if (ldlt_ok_) return true;
    ++fallbacks_;
    ready_ = factorize_lu();
    return ready_;
}

bool BorderedSolver::solve_by_elimination(const Eigen::VectorXd& f, double g, Eigen::VectorXd& x, double& y) const {
    const Eigen::VectorXd w = ldlt_.solve(f);
    y = (g - c_.dot(w)) / delta_;
    x = w - y * v_;
    return x.allFinite() && std::isfinite(y);
}

bool BorderedSolver::residual_small(const Eigen::VectorXd& f, double g, const Eigen::VectorXd& x, double y) const {
    const double r = (f - a_ * x - b_ * y).lpNorm<Eigen::Infinity>();
    const double rg = std::abs(g - c_.dot(x));
    const double xn = x.lpNorm<Eigen::Infinity>();
    const double scale = a_norm_ * xn + b_.lpNorm<Eigen::Infinity>() * std::abs(y) + f.lpNorm<Eigen::Infinity>();
    return r <= kResidualTolerance * scale && rg <= kResidualTolerance * (c_.lpNorm<1>() * xn + std::abs(g));
}

bool BorderedSolver::solve_by_lu(const Eigen::VectorXd& f, double g, Eigen::VectorXd& x, double& y) {
    if (!lu_ready_ && !factorize_lu()) return false;
    Eigen::VectorXd rhs(f.size() + 1);
    rhs.head(f.size()) = f;
    rhs[f.size()] = g;
    const Eigen::VectorXd s = lu_.solve(rhs);
    x = s.head(f.size());
    y = s[f.size()];
    return s.allFinite();
}

bool BorderedSolver::solve(const Eigen::VectorXd& f, double g, Eigen::VectorXd& x, double& y) {
    if (!ready_) return false;
    if (ldlt_ok_ && !lu_ready_) {
        // Block elimination loses accuracy as A nears singularity (its error lies along A's near
        // null vector); one refinement step on the whole system's residual restores it.
        if (solve_by_elimination(f, g, x, y)) {
            Eigen::VectorXd dx;
            double dy = 0.0;
            const Eigen::VectorXd rf = f - a_ * x - b_ * y;
            const double rg = g - c_.dot(x);
            if (solve_by_elimination(rf, rg, dx, dy)) {
                x += dx;
                y += dy;
                if (residual_small(f, g, x, y)) return true;
            }
        }
        ++fallbacks_;
    }
    return solve_by_lu(f, g, x, y);
}

bool BorderedSolver::positive_definite(const SparseMatrix& a) {
    ready_ = false;
    if (!factorize_ldlt(a)) return false;
    return (ldlt_.vectorD().array() > 0.0).all();
}

}  // namespace vi
