#include "statics/static_solution.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "forces/force_assembly.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

std::vector<int> starting_modes(const ForceSet& forces, std::vector<int> start, Eigen::Index n) {
    if (start.size() == forces.size()) return start;
    return static_modes(forces, Eigen::VectorXd::Zero(n), std::vector<int>(forces.size(), 0));
}

// Residual K q - f_ext - f_el(q) - P shape at roundoff of its terms: a relative 1e-12 of the largest
// sum of magnitudes that enters a row (|K| |q| + |f_ext| + |f_el| + |P shape|).
bool at_roundoff(const SparseMatrix& K, const Eigen::VectorXd& q, const Eigen::VectorXd& residual,
                 const Eigen::VectorXd& rhs_scale) {
    Eigen::VectorXd scale = rhs_scale;
    for (int col = 0; col < K.outerSize(); ++col) {
        for (SparseMatrix::InnerIterator it(K, col); it; ++it) scale[it.row()] += std::abs(it.value() * q[it.col()]);
    }
    const double s = scale.lpNorm<Eigen::Infinity>();
    return residual.lpNorm<Eigen::Infinity>() <= 1e-12 * s;
}

// Solves with the tangent stiffness: a dense Cholesky factor up to kDenseLimit DOFs (the way these
// static states were always solved, so the paper's results stay the same to the last digit), the
// sparse LDL^T otherwise or when the tangent is not positive definite (a softening element).
class TangentSolver {
public:
    static constexpr Eigen::Index kDenseLimit = 400;
    explicit TangentSolver(const SparseMatrix& T) {
        if (T.rows() <= kDenseLimit) {
            llt_.compute(Eigen::MatrixXd(T));
            if (llt_.info() == Eigen::Success) {
                dense_ = true;
                return;
            }
        }
        ldlt_.compute(T);
        if (ldlt_.info() != Eigen::Success || !(ldlt_.vectorD().array().abs() > 0.0).all()) {
            throw std::runtime_error("static solution: the stiffness with the closed contacts is singular "
                                     "(a mechanism, or a contact set that cannot carry the load)");
        }
    }
    [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
        if (dense_) return llt_.solve(b);
        return ldlt_.solve(b);
    }

private:
    bool dense_ = false;
    Eigen::LLT<Eigen::MatrixXd> llt_;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt_;
};

// After a Newton step: the elements' modes decided again from s.q; true when they stay and the
// residual K q - f_el(q) - load is at roundoff (load_scale: the magnitudes of the load's entries).
bool settled(const SparseMatrix& K, const ForceSet& forces, StaticState& s, const Eigen::VectorXd& load,
             const Eigen::VectorXd& load_scale) {
    std::vector<int> next = static_modes(forces, s.q, s.modes);
    if (next != s.modes) {
        s.modes = std::move(next);
        return false;
    }
    const StaticSums b = sum_static(forces, s.modes, s.q);
    return at_roundoff(K, s.q, K * s.q - b.force - load, load_scale + b.magnitude);
}

[[noreturn]] void too_many_iterations(int max_iterations) {
    throw WorkLimitReached("static solution: no equilibrium after solver.max_static_iterations = " +
                           std::to_string(max_iterations) +
                           " Newton iterations (the contact modes keep changing or Newton does not converge; "
                           "raise solver.max_static_iterations)");
}

}  // namespace

StaticState solve_static(const SparseMatrix& K, const ForceSet& forces, const Eigen::VectorXd& f_ext,
                         std::vector<int> start, int max_iterations) {
    StaticState s;
    s.q = Eigen::VectorXd::Zero(K.rows());
    s.modes = starting_modes(forces, std::move(start), K.rows());
    for (int it = 0; it < max_iterations; ++it) {
        check_run();
        const StaticSums a = sum_static(forces, s.modes, s.q, {.stiffness = true});
        const Eigen::VectorXd r = K * s.q - f_ext - a.force;
        const TangentSolver solver(with_stiffness(K, a.stiffness));
        s.q -= solver.solve(r);
        s.iterations = it + 1;
        if (settled(K, forces, s, f_ext, f_ext.cwiseAbs())) return s;
    }
    too_many_iterations(max_iterations);
}

StaticLift solve_static_lift(const SparseMatrix& K, const ForceSet& forces, const Eigen::VectorXd& shape, double target,
                             std::vector<int> start, int max_iterations) {
    StaticLift out;
    StaticState& s = out.state;
    s.q = Eigen::VectorXd::Zero(K.rows());
    s.modes = starting_modes(forces, std::move(start), K.rows());
    for (int it = 0; it < max_iterations; ++it) {
        check_run();
        const StaticSums a = sum_static(forces, s.modes, s.q, {.stiffness = true});
        const Eigen::VectorXd r = K * s.q - a.force - out.force * shape;
        const TangentSolver solver(with_stiffness(K, a.stiffness));
        // [T -shape; shape^T 0] [dq; dP] = [-r; target - shape.q], by two solves with T.
        const Eigen::VectorXd u = solver.solve(shape);
        const Eigen::VectorXd w = solver.solve(-r);
        const double compliance = shape.dot(u);
        // A point so near a clamped or pinned end that its compliance underflows (x/l = 1e-300).
        if (!(compliance > 0.0)) {
            throw InputError("initial.position: the point does not move under a static force (too close to a "
                             "clamped or pinned end)");
        }
        const double dP = (target - shape.dot(s.q) - shape.dot(w)) / compliance;
        s.q += w + dP * u;
        out.force += dP;
        s.iterations = it + 1;
        if (settled(K, forces, s, out.force * shape, std::abs(out.force) * shape.cwiseAbs())) return out;
    }
    too_many_iterations(max_iterations);
}

}  // namespace vi
