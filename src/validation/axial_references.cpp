#include "validation/axial_references.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "forces/electrostatic_pad.hpp"
#include "model/golden_section.hpp"

namespace vi {
namespace {

constexpr double pi = std::numbers::pi;

// The clamped-clamped determinant at Omega^2 = rho A omega^2 l^4 / EI and u = N0 l^2 / EI,
// divided by cosh(a) to keep it finite for the higher modes.
double clamped_determinant(double omega_bar, double u) {
    const double root = std::sqrt(u * u + 4.0 * omega_bar * omega_bar);
    const double a = std::sqrt(0.5 * (root + u)), b = std::sqrt(0.5 * (root - u));
    return (2.0 * a * b * (1.0 / std::cosh(a) - std::cos(b)) + (a * a - b * b) * std::tanh(a) * std::sin(b));
}

// Nondimensional half-span state: u, u', u'', u''', int_0^xi u'^2 (u = w / g, xi = x / l).
using State = Eigen::Matrix<double, 5, 1>;

// Unknowns p = (u''(0), u'''(0), lambda, n): u'''' = n u'' + lambda / (1 - u)^2.
// Residuals at mid-span: u' = 0, u''' = 0 (symmetry), u = delta, and n = n0 + kappa int_0^1 u'^2.
Eigen::Vector4d half_span_residual(const Eigen::Vector4d& p, double delta, double n0, double kappa) {
    const int steps = 2000;
    const double h = 0.5 / steps;
    State y;
    y << 0, 0, p[0], p[1], 0;
    const auto rhs = [&](const State& s) {
        State d;
        d << s[1], s[2], s[3], p[3] * s[2] + p[2] / ((1 - s[0]) * (1 - s[0])), s[1] * s[1];
        return d;
    };
    for (int i = 0; i < steps; ++i) {
        const State k1 = rhs(y), k2 = rhs(y + 0.5 * h * k1), k3 = rhs(y + 0.5 * h * k2), k4 = rhs(y + h * k3);
        y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return {y[1], y[3], y[0] - delta, p[3] - n0 - kappa * 2.0 * y[4]};
}

}  // namespace

double pinned_pinned_axial_omega(const AxialBeam& b, int n) {
    const double k = n * pi / b.length;
    return k * k * std::sqrt(b.EI / b.rhoA) * std::sqrt(1.0 + b.N0 / (k * k * b.EI));
}

std::vector<double> clamped_clamped_axial_omegas(const AxialBeam& b, int count) {
    const double u = b.N0 * b.length * b.length / b.EI;
    const double to_omega = std::sqrt(b.EI / b.rhoA) / (b.length * b.length);
    std::vector<double> roots;
    // Scan Omega in steps of 0.05 (roots lie at least ~ 20 apart), bisect each sign change.
    const double step = 0.05;
    double lo = step, f_lo = clamped_determinant(lo, u);
    for (int k = 2; k < 200000 && static_cast<int>(roots.size()) < count; ++k) {
        const double hi = k * step, f_hi = clamped_determinant(hi, u);
        if ((f_lo < 0) != (f_hi < 0)) {
            double a = lo, fa = f_lo, c = hi;
            for (int it = 0; it < 200 && c - a > 1e-15 * c; ++it) {
                const double mid = 0.5 * (a + c), fm = clamped_determinant(mid, u);
                if ((fm < 0) == (fa < 0)) {
                    a = mid;
                    fa = fm;
                } else {
                    c = mid;
                }
            }
            roots.push_back(0.5 * (a + c) * to_omega);
        }
        lo = hi;
        f_lo = f_hi;
    }
    if (static_cast<int>(roots.size()) < count) throw std::runtime_error("clamped_clamped_axial_omegas: roots not found");
    return roots;
}

BridgePullin bridge_pullin_shooting(const AxialBeam& b, double gap, double electrode_width, bool stretching) {
    const double n0 = b.N0 * b.length * b.length / b.EI;
    const double kappa = stretching ? b.EA * gap * gap / (2.0 * b.EI) : 0.0;
    Eigen::Vector4d p(0, 0, 0, n0);
    // lambda at a prescribed mid-span travel delta, by Newton (bounded) from the last solution.
    const auto lambda_at = [&](double delta) {
        for (int it = 0; it < 40; ++it) {
            const Eigen::Vector4d r = half_span_residual(p, delta, n0, kappa);
            Eigen::Matrix4d j;
            for (int c = 0; c < 4; ++c) {
                Eigen::Vector4d d = p;
                d[c] += 1e-7 * (1 + std::abs(p[c]));
                j.col(c) = (half_span_residual(d, delta, n0, kappa) - r) / (d[c] - p[c]);
            }
            const Eigen::Vector4d dp = j.fullPivLu().solve(-r);
            p += dp;
            if (dp.norm() < 1e-13 * (1 + p.norm())) return p[2];
        }
        throw std::runtime_error("bridge_pullin_shooting: Newton did not converge in 40 iterations");
    };
    double best_delta = 0.0, best = 0.0;
    for (int step = 1; step <= 95; ++step) {
        const double l = lambda_at(0.01 * step);
        if (l < best) break;  // past the fold: lambda falls from here on
        best = l;
        best_delta = 0.01 * step;
    }
    // The largest lambda around the best grid point.
    const GoldenSectionPeak peak = golden_section_max(lambda_at, best_delta - 0.01, best_delta + 0.01, 1e-12);
    const double delta = peak.x;
    const double lambda = peak.value;
    // lambda = eps0 w_e V^2 l^4 / (2 EI g^3).
    const double l4 = std::pow(b.length, 4);
    return {std::sqrt(2.0 * b.EI * gap * gap * gap * lambda / (kEpsilon0 * electrode_width * l4)), delta};
}

}  // namespace vi
