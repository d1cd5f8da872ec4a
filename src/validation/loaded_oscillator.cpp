#include "validation/loaded_oscillator.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <memory>
#include <stdexcept>

#include "forces/point_load_element.hpp"

namespace vi {

double LoadedOscillator::omega() const { return std::sqrt(stiffness / mass); }

double LoadedOscillator::period() const { return 2.0 * std::numbers::pi / omega(); }

TransientProblem LoadedOscillator::problem(double t_end, double output_step) const {
    TransientProblem p;
    p.M = Eigen::MatrixXd::Constant(1, 1, mass).sparseView();
    p.K = Eigen::MatrixXd::Constant(1, 1, stiffness).sparseView();
    p.alpha = 2.0 * zeta * omega();
    p.q0 = Eigen::VectorXd::Constant(1, q0);
    p.v0 = Eigen::VectorXd::Zero(1);
    p.forces.push_back(std::make_shared<PointLoadElement>("loads[0]", std::vector<int>{0}, std::vector<double>{1.0},
                                                          force, g, -1.0));
    p.watched_dof = 0;
    p.t_end = t_end;
    p.output_step = output_step;
    return p;
}

double LoadedOscillator::response(double t) const {
    using cd = std::complex<double>;
    const double w = omega(), wd = w * std::sqrt(1.0 - zeta * zeta), qs = force / stiffness;
    // A particular solution qp (value qp0 and slope vp0 at s = 0) plus the free response that
    // starts the motion from (a0, 0) at s = 0.
    auto with_free = [&](double s, double a0, double qp0, double vp0, double qp) {
        const double a = a0 - qp0, b = (-vp0 + zeta * w * a) / wd;
        return qp + std::exp(-zeta * w * s) * (a * std::cos(wd * s) + b * std::sin(wd * s));
    };
    switch (g.kind) {
        case TimeFunction::Kind::harmonic: {
            // q'' + 2 zeta w q' + w^2 q = F/m (offset + Im e^(i (W t + phase))).
            const double W = 2.0 * std::numbers::pi * g.frequency_hz;
            const cd h = (force / mass) / cd(w * w - W * W, 2.0 * zeta * w * W);
            auto qp = [&](double s) { return qs * g.offset + std::imag(h * std::exp(cd(0.0, W * s + g.phase))); };
            const double vp0 = std::imag(h * cd(0.0, W) * std::exp(cd(0.0, g.phase)));
            return with_free(t, q0, qp(0.0), vp0, qp(t));
        }
        case TimeFunction::Kind::step: {
            if (t < g.t_on) return with_free(t, q0, 0.0, 0.0, 0.0);
            // Superposition: the free motion from q0, plus the step's response from rest.
            return with_free(t, q0, 0.0, 0.0, 0.0) + with_free(t - g.t_on, 0.0, qs, 0.0, qs);
        }
        case TimeFunction::Kind::table: {
            const bool ramp = g.times.size() == 2 && g.times[0] == 0.0 && g.values == std::vector<double>{0.0, 1.0};
            if (!ramp || zeta != 0.0 || q0 != 0.0) break;
            const double t1 = g.times[1];
            if (t <= t1) return qs * (t / t1 - std::sin(w * t) / (w * t1));
            return qs * (1.0 - (std::sin(w * t) - std::sin(w * (t - t1))) / (w * t1));
        }
        case TimeFunction::Kind::constant: break;
    }
    throw std::invalid_argument("LoadedOscillator::response: no closed form for this load");
}

LoadResponseError load_response_error(const LoadedOscillator& o, const TransientResult& r, double scale) {
    LoadResponseError err;
    const EnergyLedger& e0 = r.history.energy.front();
    const double E0 = e0.kinetic + e0.strain;
    double big = E0;
    for (const EnergyLedger& e : r.history.energy) {
        big = std::max({big, e.kinetic + e.strain, std::abs(e.external_work), e.rayleigh_dissipated});
    }
    for (std::size_t i = 0; i < r.history.t.size(); ++i) {
        err.response = std::max(err.response, std::abs(r.history.watched_v[i] - o.response(r.history.t[i])) / scale);
        const EnergyLedger& e = r.history.energy[i];
        err.ledger = std::max(err.ledger, std::abs(e.kinetic + e.strain + e.rayleigh_dissipated - e.external_work - E0) / big);
    }
    return err;
}

}  // namespace vi
