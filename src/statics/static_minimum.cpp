#include "statics/static_minimum.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "forces/force_assembly.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The elements' part at q, each in its static mode: force, |terms| per row, energy, tangent -df/dq.
struct Terms {
    StaticSums sums;
    std::vector<int> modes;
};

Terms element_terms(const ForceSet& forces, const Eigen::VectorXd& q, bool with_tangent) {
    Terms t;
    t.modes = static_modes(forces, q, std::vector<int>(forces.size(), 0));
    t.sums = sum_static(forces, t.modes, q, {.stiffness = with_tangent, .energy = true});
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
    return 0.5 * q.dot(K * q) - f_ext.dot(q) + element_terms(forces, q, false).sums.energy;
}

StaticState minimize_static_energy(const SparseMatrix& K, const ForceSet& forces, const Eigen::VectorXd& f_ext,
                                   Eigen::VectorXd start, int max_iterations, double tolerance) {
    StaticState s;
    s.q = std::move(start);
    const auto residual_scale = [&](const Eigen::VectorXd& q, const Terms& t) {
        Eigen::VectorXd scale = f_ext.cwiseAbs() + t.sums.magnitude;
        for (int col = 0; col < K.outerSize(); ++col) {
            for (SparseMatrix::InnerIterator it(K, col); it; ++it) scale[it.row()] += std::abs(it.value() * q[it.col()]);
        }
        return inf_norm(scale);
    };
    Terms t = element_terms(forces, s.q, true);
    double pi = 0.5 * s.q.dot(K * s.q) - f_ext.dot(s.q) + t.sums.energy;
    for (int it = 0; it < max_iterations; ++it) {
        check_run();
        const Eigen::VectorXd g = K * s.q - f_ext - t.sums.force;
        s.modes = t.modes;
        s.iterations = it;
        if (inf_norm(g) <= tolerance * residual_scale(s.q, t)) return s;
        const Eigen::VectorXd p = -descent_step(with_stiffness(K, t.sums.stiffness), g);
        const double slope = g.dot(p);  // < 0
        // Backtracking (Armijo) on Pi; where Pi's change is lost in rounding near the minimum, a step
        // that lowers the gradient is taken instead.
        double alpha = 1.0;
        bool taken = false;
        for (int k = 0; k < 60 && !taken; ++k, alpha *= 0.5) {
            const Eigen::VectorXd trial = s.q + alpha * p;
            Terms tt = element_terms(forces, trial, true);
            const double pt = 0.5 * trial.dot(K * trial) - f_ext.dot(trial) + tt.sums.energy;
            const double rounding = 1e-12 * (energy_scale(K, trial) + tt.sums.energy_magnitude);
            const bool lower = pt <= pi + 1e-4 * alpha * slope;
            const bool flat = std::abs(pt - pi) <= rounding &&
                              inf_norm(K * trial - f_ext - tt.sums.force) < inf_norm(g);
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
