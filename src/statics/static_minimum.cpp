#include "statics/static_minimum.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The elements' part at q, each in its static mode: force, |terms| per row, energy, tangent -df/dq.
struct Terms {
    Eigen::VectorXd force, scale;
    double energy = 0.0;
    double energy_scale = 0.0;  // sum of |stored energy| over the elements
    std::vector<Eigen::Triplet<double>> tangent;
    std::vector<int> modes;
};

Terms element_terms(const ForceSet& forces, const Eigen::VectorXd& q, bool with_tangent) {
    Terms t;
    t.force = Eigen::VectorXd::Zero(q.size());
    t.scale = Eigen::VectorXd::Zero(q.size());
    t.modes.assign(forces.size(), 0);
    std::vector<double> ql, vl, fl, dq, dv;
    for (std::size_t i = 0; i < forces.size(); ++i) {
        const ForceElement& e = *forces[i];
        if (!e.in_static_state()) continue;
        const std::vector<int>& d = e.dofs();
        const std::size_t m = d.size();
        ql.assign(m, 0.0);
        vl.assign(m, 0.0);
        fl.assign(m, 0.0);
        for (std::size_t k = 0; k < m; ++k) ql[k] = q[d[k]];
        const ElementState s{0.0, ql.data(), vl.data(), nullptr};
        const int mode = e.static_mode(s);
        t.modes[i] = mode;
        e.add_force(s, mode, fl.data());
        const double stored = e.stored_energy(s, mode);
        t.energy += stored;
        t.energy_scale += std::abs(stored);
        for (std::size_t r = 0; r < m; ++r) {
            t.force[d[r]] += fl[r];
            t.scale[d[r]] += std::abs(fl[r]);
        }
        if (!with_tangent) continue;
        dq.assign(m * m, 0.0);
        dv.assign(m * m, 0.0);
        e.add_tangent(s, mode, dq.data(), dv.data());
        for (std::size_t r = 0; r < m; ++r) {
            for (std::size_t c = 0; c < m; ++c) {
                if (dq[r * m + c] != 0.0) t.tangent.emplace_back(d[r], d[c], -dq[r * m + c]);
            }
        }
    }
    return t;
}

// Solves H x = b with H + mu D positive definite, D = diag(|H|), mu = 0 or the smallest of
// 1e-10, 1e-9, ... that makes it so (a Levenberg shift: the step is then a descent direction).
Eigen::VectorXd descent_step(const SparseMatrix& H, const Eigen::VectorXd& b) {
    const Eigen::VectorXd diag = H.diagonal().cwiseAbs();
    const double floor = 1e-300 + diag.maxCoeff() * 1e-16;
    double mu = 0.0;
    for (int attempt = 0; attempt < 30; ++attempt) {
        SparseMatrix A = H;
        if (mu > 0.0) {
            for (Eigen::Index i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += mu * std::max(diag[i], floor);
        }
        Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);
        if (ldlt.info() == Eigen::Success && (ldlt.vectorD().array() > 0.0).all()) return ldlt.solve(b);
        mu = mu == 0.0 ? 1e-10 : mu * 10.0;
    }
    throw std::runtime_error("static minimum: the tangent stiffness stays indefinite under every shift tried");
}

// The sum of magnitudes of the terms of q^T K q / 2: the scale of its rounding error [J].
double energy_scale(const SparseMatrix& K, const Eigen::VectorXd& q) {
    double sum = 0.0;
    for (int col = 0; col < K.outerSize(); ++col) {
        for (SparseMatrix::InnerIterator it(K, col); it; ++it) sum += std::abs(it.value() * q[it.row()] * q[it.col()]);
    }
    return 0.5 * sum;
}

double inf_norm(const Eigen::VectorXd& x) { return x.size() ? x.lpNorm<Eigen::Infinity>() : 0.0; }

}  // namespace

double static_potential(const SparseMatrix& K, const ForceSet& forces, const Eigen::VectorXd& f_ext,
                        const Eigen::VectorXd& q) {
    return 0.5 * q.dot(K * q) - f_ext.dot(q) + element_terms(forces, q, false).energy;
}

StaticState minimize_static_energy(const SparseMatrix& K, const ForceSet& forces, const Eigen::VectorXd& f_ext,
                                   Eigen::VectorXd start, int max_iterations, double tolerance) {
    StaticState s;
    s.q = std::move(start);
    const auto residual_scale = [&](const Eigen::VectorXd& q, const Terms& t) {
        Eigen::VectorXd scale = f_ext.cwiseAbs() + t.scale;
        for (int col = 0; col < K.outerSize(); ++col) {
            for (SparseMatrix::InnerIterator it(K, col); it; ++it) scale[it.row()] += std::abs(it.value() * q[it.col()]);
        }
        return inf_norm(scale);
    };
    Terms t = element_terms(forces, s.q, true);
    double pi = 0.5 * s.q.dot(K * s.q) - f_ext.dot(s.q) + t.energy;
    for (int it = 0; it < max_iterations; ++it) {
        check_run();
        const Eigen::VectorXd g = K * s.q - f_ext - t.force;
        s.modes = t.modes;
        s.iterations = it;
        if (inf_norm(g) <= tolerance * residual_scale(s.q, t)) return s;
        SparseMatrix T(K.rows(), K.cols());
        T.setFromTriplets(t.tangent.begin(), t.tangent.end());
        const Eigen::VectorXd p = -descent_step(K + T, g);
        const double slope = g.dot(p);  // < 0
        // Backtracking (Armijo) on Pi; where Pi's change is lost in rounding near the minimum, a step
        // that lowers the gradient is taken instead.
        double alpha = 1.0;
        bool taken = false;
        for (int k = 0; k < 60 && !taken; ++k, alpha *= 0.5) {
            const Eigen::VectorXd trial = s.q + alpha * p;
            Terms tt = element_terms(forces, trial, true);
            const double pt = 0.5 * trial.dot(K * trial) - f_ext.dot(trial) + tt.energy;
            const double rounding = 1e-12 * (energy_scale(K, trial) + tt.energy_scale);
            const bool lower = pt <= pi + 1e-4 * alpha * slope;
            const bool flat = std::abs(pt - pi) <= rounding &&
                              inf_norm(K * trial - f_ext - tt.force) < inf_norm(g);
            if (lower || flat) {
                s.q = trial;
                t = std::move(tt);
                pi = pt;
                taken = true;
            }
        }
        if (!taken) {
            throw std::runtime_error("static minimum: no step along the Newton direction lowers the potential energy "
                                     "(at iteration " + std::to_string(it) + ")");
        }
    }
    throw WorkLimitReached("static minimum: not settled after solver.max_static_iterations = " +
                           std::to_string(max_iterations) + " Newton steps (raise solver.max_static_iterations)");
}

}  // namespace vi
