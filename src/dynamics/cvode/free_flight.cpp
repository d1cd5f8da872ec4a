#include "dynamics/cvode/free_flight.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace vi::cvode_detail {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// f(tau) above the roundoff of its terms (their magnitudes times a few ulps): a value at that level
// is no sign.
bool clearly_positive(const ExpSignal& f, double tau) {
    double value = 0.0, size = 0.0;
    for (Eigen::Index k = 0; k < f.A.size(); ++k) {
        const cd v = f.A[k] * fast_exp((*f.lambda)[k], tau);
        value += v.real();
        size += std::abs(v);
    }
    for (const ExpTerm& t : f.terms) {
        const cd v = term_derivative(t, tau, 0);
        value += v.real();
        size += std::abs(v);
    }
    return value > 64.0 * kEps * size;
}

}  // namespace

FreeFlight::FreeFlight(const ModalSystem& system) : sys_(system) {
    // A nodal state has no modes to fly in.
    if (sys_.nodal()) {
        usable_ = false;
        return;
    }
    const int r = sys_.basis_size();
    const Eigen::VectorXd& w = sys_.basis().omega;
    const Eigen::VectorXd& d = sys_.rayleigh();
    std::vector<cd> lambda;
    for (int i = 0; i < r; ++i) {
        const double half = 0.5 * d[i], w2 = w[i] * w[i];
        const double disc = w2 - half * half;
        // Near critical damping the two exponents merge and the amplitudes of each grow as
        // 1 / (their distance), cancelling: digits lost there.
        if (!(std::abs(disc) > 1e-6 * std::max(w2, half * half))) {
            usable_ = false;
            return;
        }
        if (disc > 0.0) {
            lambda.emplace_back(-half, std::sqrt(disc));
            vector_.push_back(i);
        } else {
            const double s = std::sqrt(-disc);
            lambda.emplace_back(-half + s, 0.0);
            lambda.emplace_back(-half - s, 0.0);
            vector_.push_back(i);
            vector_.push_back(i);
        }
    }
    lambda_ = Eigen::Map<Eigen::VectorXcd>(lambda.data(), static_cast<Eigen::Index>(lambda.size()));
    E_ = Eigen::VectorXcd::Zero(lambda_.size());
    // The search's smallest step as the exact solver's: 1e-9 of the lowest vector's period.
    h_min_ = r > 0 && w[0] > 0.0 ? 1e-9 * 2.0 * std::numbers::pi / w[0] : 0.0;
}

std::optional<std::vector<FreeMode>> FreeFlight::free_modes(const std::vector<int>& modes) const {
    std::vector<FreeMode> out;
    for (int e = 0; e < sys_.elements(); ++e) {
        std::optional<FreeMode> m = sys_.element(e).free_mode(modes[static_cast<std::size_t>(e)]);
        if (!m) return std::nullopt;
        out.push_back(std::move(*m));
    }
    return out;
}

void FreeFlight::start(double t0, const double* y) {
    const int r = sys_.basis_size();
    t0_ = t0;
    y0_ = Eigen::Map<const Eigen::VectorXd>(y, sys_.size());
    for (Eigen::Index k = 0; k < lambda_.size(); ++k) {
        const int i = vector_[static_cast<std::size_t>(k)];
        const double q = y[i], v = y[r + i];
        const cd l = lambda_[k];
        if (l.imag() != 0.0) {
            // eta = exp(-D tau / 2) (q cos + b sin), b = (v + D q / 2) / w_d = Re[(q - i b) exp(lambda tau)].
            E_[k] = cd(q, -(v - l.real() * q) / l.imag());
        } else if (k + 1 < lambda_.size() && vector_[static_cast<std::size_t>(k + 1)] == i) {
            // Two real exponents l1, l2: A1 + A2 = q, l1 A1 + l2 A2 = v.
            const double l1 = l.real(), l2 = lambda_[k + 1].real();
            const double a1 = (v - l2 * q) / (l1 - l2);
            E_[k] = a1;
            E_[k + 1] = q - a1;
            ++k;
        }
    }
    evaluations_ = 0;
}

void FreeFlight::state(double t, double* out) const {
    const int r = sys_.basis_size();
    const double tau = t - t0_;
    Eigen::Map<Eigen::VectorXd>(out, sys_.size()) = y0_;
    const Eigen::VectorXd& d = sys_.rayleigh();
    for (int i = 0; i < r; ++i) out[i] = out[r + i] = 0.0;
    double rayleigh = 0.0;
    for (Eigen::Index k = 0; k < lambda_.size(); ++k) {
        const int i = vector_[static_cast<std::size_t>(k)];
        const cd e = fast_exp(lambda_[k], tau);
        const cd b = lambda_[k] * E_[k];
        out[i] += (E_[k] * e).real();
        out[r + i] += (b * e).real();
        // D_i times the integral of eta_i'^2 = (Re sum b_k exp)^2 over [0, tau]: with Re(x) Re(z) =
        // Re(x z + x conj(z)) / 2, pairs of this vector's exponents.
        for (Eigen::Index l = k; l < lambda_.size() && vector_[static_cast<std::size_t>(l)] == i; ++l) {
            const cd c = lambda_[l] * E_[l];
            const double twice = l == k ? 1.0 : 2.0;
            const cd pair = b * c * exp_moment(lambda_[k] + lambda_[l], 0, tau) +
                            b * std::conj(c) * exp_moment(lambda_[k] + std::conj(lambda_[l]), 0, tau);
            rayleigh += d[i] * twice * 0.5 * pair.real();
        }
    }
    out[sys_.rayleigh_index()] += rayleigh;
}

ExpSignal FreeFlight::row_signal(const Eigen::RowVectorXd& aq, const Eigen::RowVectorXd& av) const {
    ExpSignal f;
    f.lambda = &lambda_;
    f.A.resize(lambda_.size());
    for (Eigen::Index k = 0; k < lambda_.size(); ++k) {
        const int i = vector_[static_cast<std::size_t>(k)];
        f.A[k] = (aq[i] + av[i] * lambda_[k]) * E_[k];
    }
    return f;
}

ExpSignal FreeFlight::part_signal(int e, const LinearPart& p) const {
    const Eigen::MatrixXd& rows = sys_.rows(e);
    const Eigen::Index n = rows.rows();
    if (static_cast<Eigen::Index>(p.wq.size()) != n || static_cast<Eigen::Index>(p.wv.size()) != n) {
        throw std::invalid_argument("FreeFlight: " + sys_.element(e).name() + "'s free mode has weights of the wrong size");
    }
    const Eigen::RowVectorXd aq = Eigen::Map<const Eigen::RowVectorXd>(p.wq.data(), n) * rows;
    const Eigen::RowVectorXd av = Eigen::Map<const Eigen::RowVectorXd>(p.wv.data(), n) * rows;
    ExpSignal f = row_signal(aq, av);
    if (p.offset != 0.0) f.terms.push_back({cd(p.offset, 0.0), cd(0.0, 0.0), 0});
    return f;
}

CrossingSearch FreeFlight::search(double t_end, long* budget) const {
    CrossingSearch cs;
    cs.h_min = h_min_;
    // Roots to a few ulps of the absolute time, as the exact solver's.
    cs.t_tol = 4.0 * kEps * std::abs(t_end);
    cs.budget = budget;
    return cs;
}

std::optional<double> FreeFlight::first_switch(int e, const FreeMode& m, double t_end, long* budget) {
    if (m.parts.empty()) return std::nullopt;
    std::vector<ExpSignal> parts;
    for (const LinearPart& p : m.parts) parts.push_back(part_signal(e, p));
    const CrossingSearch cs = search(t_end, budget);
    const double span = t_end - t0_;
    double tau = 0.0;
    // Whether a part is rising through zero at tau (the search's reading of a value at roundoff).
    std::vector<bool> rising(parts.size(), false);
    // The smallest part turns positive where the last of them does: a part not clearly positive at
    // tau is searched for its crossing, and the rest again from there, until every part is positive.
    // Each round moves tau to a later crossing; the search's budget bounds the rounds.
    for (;;) {
        bool all = true;
        for (std::size_t k = 0; k < parts.size() && all; ++k) {
            if (rising[k] || clearly_positive(parts[k], tau)) continue;
            const std::optional<double> hit = first_upcrossing(parts[k], tau, span, cs, &evaluations_);
            if (!hit) return std::nullopt;
            if (*hit <= tau) {
                rising[k] = true;
                continue;
            }
            tau = *hit;
            rising.assign(parts.size(), false);
            rising[k] = true;  // the search returns the first point past the crossing
            all = false;
        }
        if (all) return t0_ + tau;
    }
}

SignalMaximum FreeFlight::maximum(const Eigen::RowVectorXd& row, double t_end, double floor, long* budget) {
    const ExpSignal f = row_signal(row, Eigen::RowVectorXd::Zero(row.size()));
    const CrossingSearch cs = search(t_end, budget);
    // As the exact solver's y_max: to 1e-9 of the maximum, never finer than roundoff of the signal.
    SignalMaximum m = global_maximum(f, t_end - t0_, 64.0 * kEps, 1e-9, cs.t_tol, &evaluations_, floor, 1.0, budget);
    if (m.tau >= 0.0) m.tau += t0_;
    return m;
}

}  // namespace vi::cvode_detail
