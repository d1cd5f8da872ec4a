#include "forces/force_assembly.hpp"

#include <cmath>

namespace vi {

const ElementState& ElementAssembler::gather(const ForceElement& e, std::span<const int> at, const double* q,
                                             const double* v, const double* a, double t) {
    element_ = &e;
    at_ = at;
    const std::size_t m = at.size();
    q_.resize(m);
    v_.resize(m);
    for (std::size_t k = 0; k < m; ++k) q_[k] = q[at[k]];
    for (std::size_t k = 0; k < m; ++k) v_[k] = v ? v[at[k]] : 0.0;
    if (a) {
        a_.resize(m);
        for (std::size_t k = 0; k < m; ++k) a_[k] = a[at[k]];
    }
    state_ = ElementState{t, q_.data(), v_.data(), a ? a_.data() : nullptr};
    return state_;
}

const ElementState& ElementAssembler::gather_rest(const ForceElement& e) {
    element_ = &e;
    at_ = e.dofs();
    q_.assign(at_.size(), 0.0);
    v_.assign(at_.size(), 0.0);
    state_ = ElementState{0.0, q_.data(), v_.data(), nullptr};
    return state_;
}

const std::vector<double>& ElementAssembler::force(int mode) {
    force_.assign(at_.size(), 0.0);
    element_->add_force(state_, mode, force_.data());
    return force_;
}

double ElementAssembler::force_and_power(int mode) {
    force_.assign(at_.size(), 0.0);
    return element_->add_force_and_power(state_, mode, force_.data());
}

void ElementAssembler::tangent(int mode) {
    const std::size_t m = at_.size();
    dfdq_.assign(m * m, 0.0);
    dfdv_.assign(m * m, 0.0);
    element_->add_tangent(state_, mode, dfdq_.data(), dfdv_.data());
}

double ElementAssembler::force_sum() const {
    double sum = 0.0;
    for (double x : force_) sum += x;
    return sum;
}

void ElementAssembler::scatter_force(double factor, double* f) const {
    for (std::size_t k = 0; k < at_.size(); ++k) f[at_[k]] += factor * force_[k];
}

void ElementAssembler::scatter_magnitude(double factor, Eigen::VectorXd& m) const {
    for (std::size_t k = 0; k < at_.size(); ++k) m[at_[k]] += std::abs(factor * force_[k]);
}

void ElementAssembler::scatter_stiffness(double factor, std::vector<Eigen::Triplet<double>>& triplets) const {
    const std::size_t m = at_.size();
    for (std::size_t r = 0; r < m; ++r) {
        for (std::size_t c = 0; c < m; ++c) {
            if (dfdq_[r * m + c] != 0.0) triplets.emplace_back(at_[r], at_[c], -factor * dfdq_[r * m + c]);
        }
    }
}

StaticSums sum_static(const ForceSet& forces, const std::vector<int>& modes, const Eigen::VectorXd& q,
                      StaticTerms terms) {
    StaticSums out;
    out.force = Eigen::VectorXd::Zero(q.size());
    out.magnitude = Eigen::VectorXd::Zero(q.size());
    thread_local ElementAssembler a;
    for (std::size_t i = 0; i < forces.size(); ++i) {
        const ForceElement& e = *forces[i];
        if (!e.in_static_state()) continue;
        a.gather(e, q);
        a.force(modes[i]);
        a.scatter_force(1.0, out.force);
        a.scatter_magnitude(1.0, out.magnitude);
        if (terms.energy) {
            const double stored = e.stored_energy(a.state(), modes[i]);
            out.energy += stored;
            out.energy_magnitude += std::abs(stored);
        }
        if (terms.stiffness) {
            a.tangent(modes[i]);
            a.scatter_stiffness(1.0, out.stiffness);
        }
    }
    return out;
}

std::vector<int> static_modes(const ForceSet& forces, const Eigen::VectorXd& q, std::vector<int> current) {
    thread_local ElementAssembler a;
    for (std::size_t i = 0; i < forces.size(); ++i) {
        const ForceElement& e = *forces[i];
        if (e.in_static_state()) current[i] = e.static_mode(a.gather(e, q));
    }
    return current;
}

Eigen::SparseMatrix<double> with_stiffness(const Eigen::SparseMatrix<double>& K,
                                           const std::vector<Eigen::Triplet<double>>& triplets) {
    Eigen::SparseMatrix<double> T(K.rows(), K.cols());
    T.setFromTriplets(triplets.begin(), triplets.end());
    return K + T;
}

}  // namespace vi
