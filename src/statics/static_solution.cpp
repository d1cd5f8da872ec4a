#include "statics/static_solution.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The elements' part of the static equations at q in the given modes: their force and the tangent
// K - df/dq. Elements that do not act statically contribute nothing.
struct Assembled {
    Eigen::VectorXd force;  // sum of element forces
    Eigen::VectorXd scale;  // sum of |terms| per DOF, for the roundoff level of the residual
    SparseMatrix tangent;   // K - df/dq
};

Assembled assemble(const SparseMatrix& K, const ForceSet& forces, const std::vector<int>& modes,
                   const Eigen::VectorXd& q) {
    const Eigen::Index n = K.rows();
    Assembled a;
    a.force = Eigen::VectorXd::Zero(n);
    a.scale = Eigen::VectorXd::Zero(n);
    std::vector<Eigen::Triplet<double>> trip;
    std::vector<double> ql, vl, fl, dq, dv;
    for (std::size_t i = 0; i < forces.size(); ++i) {
        const ForceElement& e = *forces[i];
        if (!e.in_static_state()) continue;
        const std::vector<int>& d = e.dofs();
        const std::size_t m = d.size();
        ql.assign(m, 0.0);
        vl.assign(m, 0.0);
        fl.assign(m, 0.0);
        dq.assign(m * m, 0.0);
        dv.assign(m * m, 0.0);
        for (std::size_t k = 0; k < m; ++k) ql[k] = q[d[k]];
        const ElementState s{0.0, ql.data(), vl.data(), nullptr};
        e.add_force(s, modes[i], fl.data());
        e.add_tangent(s, modes[i], dq.data(), dv.data());
        for (std::size_t r = 0; r < m; ++r) {
            a.force[d[r]] += fl[r];
            a.scale[d[r]] += std::abs(fl[r]);
            for (std::size_t c = 0; c < m; ++c) {
                if (dq[r * m + c] != 0.0) trip.emplace_back(d[r], d[c], -dq[r * m + c]);
            }
        }
    }
    SparseMatrix T(n, n);
    T.setFromTriplets(trip.begin(), trip.end());
    a.tangent = K + T;
    return a;
}

std::vector<int> static_modes(const ForceSet& forces, const Eigen::VectorXd& q, const std::vector<int>& current) {
    std::vector<int> out = current;
    std::vector<double> ql, vl;
    for (std::size_t i = 0; i < forces.size(); ++i) {
        const ForceElement& e = *forces[i];
        if (!e.in_static_state()) continue;
        const std::vector<int>& d = e.dofs();
        ql.assign(d.size(), 0.0);
        vl.assign(d.size(), 0.0);
        for (std::size_t k = 0; k < d.size(); ++k) ql[k] = q[d[k]];
        out[i] = e.static_mode(ElementState{0.0, ql.data(), vl.data(), nullptr});
    }
    return out;
}

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
    const Assembled b = assemble(K, forces, s.modes, s.q);
    return at_roundoff(K, s.q, K * s.q - b.force - load, load_scale + b.scale);
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
        const Assembled a = assemble(K, forces, s.modes, s.q);
        const Eigen::VectorXd r = K * s.q - f_ext - a.force;
        const TangentSolver solver(a.tangent);
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
        const Assembled a = assemble(K, forces, s.modes, s.q);
        const Eigen::VectorXd r = K * s.q - a.force - out.force * shape;
        const TangentSolver solver(a.tangent);
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
