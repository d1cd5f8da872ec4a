#include "validation/switch_collapse_reference.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace vi {
namespace {

constexpr double kEps0 = 8.8541878128e-12;  // vacuum permittivity [F/m]

// beta_n l: the n-th root of 1 + cos x cosh x = 0 (clamped-free), by Newton on cos x + 1 / cosh x.
double clamped_free_root(int n) {
    double x = n == 1 ? 1.8751 : (2.0 * n - 1.0) * std::numbers::pi / 2.0;
    for (int it = 0; it < 50; ++it) {
        const double f = std::cos(x) + 1.0 / std::cosh(x);
        const double df = -std::sin(x) - std::tanh(x) / std::cosh(x);
        const double dx = f / df;
        x -= dx;
        if (std::abs(dx) < 1e-15 * x) break;
    }
    return x;
}

// The clamped-free mode shape cosh z - cos z - sigma (sinh z - sin z), z = beta x / l, written with
// 1 - sigma computed apart so that the growing exponentials do not cancel at high modes.
struct ModeShape {
    double beta = 0.0, one_minus_sigma = 0.0, scale = 1.0;
    [[nodiscard]] double operator()(double xi) const {
        const double z = beta * xi, sigma = 1.0 - one_minus_sigma;
        return scale * (0.5 * (one_minus_sigma * std::exp(z) + (1.0 + sigma) * std::exp(-z)) - std::cos(z) + sigma * std::sin(z));
    }
};

ModeShape mode_shape(double beta) {
    ModeShape m;
    m.beta = beta;
    m.one_minus_sigma = (std::sin(beta) - std::cos(beta) - std::exp(-beta)) / (std::sinh(beta) + std::sin(beta));
    return m;
}

// Three-point Gauss-Legendre on `pieces` equal parts of [a, b]: abscissae and weights.
void gauss3(double a, double b, int pieces, std::vector<double>& x, std::vector<double>& w) {
    const double r = std::sqrt(0.6), h = (b - a) / pieces;
    for (int i = 0; i < pieces; ++i) {
        const double c = a + (i + 0.5) * h;
        for (const auto& [u, wt] : {std::pair{-r, 5.0 / 9.0}, std::pair{0.0, 8.0 / 9.0}, std::pair{r, 5.0 / 9.0}}) {
            x.push_back(c + 0.5 * h * u);
            w.push_back(0.5 * h * wt);
        }
    }
}

class SwitchRom {
public:
    SwitchRom(const CantileverSwitchSpec& s, double voltage) : s_(s) {
        const int n = s.modes;
        const double area = s.width * s.thickness, ei = s.youngs_modulus * s.width * std::pow(s.thickness, 3) / 12.0;
        mass_ = s.density * area * s.length;  // the modal mass of shapes with integral phi^2 dxi = 1
        omega_.resize(n);
        std::vector<ModeShape> shapes;
        std::vector<double> xn, wn;
        gauss3(0.0, 1.0, 400, xn, wn);
        for (int k = 0; k < n; ++k) {
            const double beta = clamped_free_root(k + 1);
            omega_[k] = beta * beta * std::sqrt(ei / (s.density * area)) / (s.length * s.length);
            ModeShape m = mode_shape(beta);
            double norm = 0.0;
            for (std::size_t i = 0; i < xn.size(); ++i) norm += wn[i] * m(xn[i]) * m(xn[i]);
            m.scale = 1.0 / std::sqrt(norm);
            shapes.push_back(m);
        }
        // Rayleigh damping through modes 1 and 2: 2 xi_n omega_n = alpha + beta omega_n^2.
        const double w1 = omega_[0], w2 = omega_[1];
        const double b = 2.0 * (w2 * s.damping_ratio_2 - w1 * s.damping_ratio_1) / (w2 * w2 - w1 * w1);
        const double a = 2.0 * w1 * s.damping_ratio_1 - b * w1 * w1;
        damping_.resize(n);
        for (int k = 0; k < n; ++k) damping_[k] = a + b * omega_[k] * omega_[k];

        std::vector<double> x, w;
        gauss3(s.electrode_from, s.electrode_to, 60, x, w);
        x.push_back(s.electrode_from);  // the span's ends are watched for the collapse, with no weight
        w.push_back(0.0);
        x.push_back(s.electrode_to);
        w.push_back(0.0);
        xi_ = Eigen::Map<Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
        weight_ = Eigen::Map<Eigen::VectorXd>(w.data(), static_cast<Eigen::Index>(w.size())) * s.length;
        shape_.resize(xi_.size(), n);
        tip_.resize(n);
        for (int k = 0; k < n; ++k) {
            for (Eigen::Index i = 0; i < xi_.size(); ++i) shape_(i, k) = shapes[k](xi_[i]);
            tip_[k] = shapes[k](1.0);
        }
        pressure_ = 0.5 * kEps0 * s.electrode_width * voltage * voltage;
        stop_damping_ = 2.0 * s.stop_damping_ratio * std::sqrt(s.stop_stiffness * mass_ / 4.0);
    }

    SwitchRomRun run() {
        const Eigen::Index n = s_.modes;
        Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * n);
        SwitchRomRun out;
        double t = 0.0;
        bool contact = switching(y) > 0.0;
        // Bounded: each step advances t by at least 3e-3 of s.step (the shortest near the electrode).
        while (t < s_.horizon) {
            const double g = narrowest_gap(y).first;
            double h = s_.step * std::min(1.0, std::pow(std::max(g / (0.5 * s_.electrode_gap), 0.02), 1.5));
            h = std::min(h, s_.horizon - t);
            Eigen::VectorXd next = rk4(y, h, contact);
            const bool crossed_stop = (switching(next) > 0.0) != contact;
            const bool collapsed = narrowest_gap(next).first <= s_.collapse_fraction * s_.electrode_gap;
            if (crossed_stop || collapsed) {
                // The first of the two events inside the step, located by bisection on the step length.
                double lo = 0.0, hi = 1.0;
                for (int it = 0; it < 60; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    const Eigen::VectorXd z = rk4(y, mid * h, contact);
                    const bool event = (switching(z) > 0.0) != contact ||
                                       narrowest_gap(z).first <= s_.collapse_fraction * s_.electrode_gap;
                    (event ? hi : lo) = mid;
                }
                next = rk4(y, hi * h, contact);
                h *= hi;
                t += h;
                y = next;
                if (narrowest_gap(y).first <= s_.collapse_fraction * s_.electrode_gap) {
                    out.collapsed = true;
                    out.collapse_time = t;
                    out.collapse_x = narrowest_gap(y).second;
                    return out;
                }
                contact = !contact;
                ++out.contact_switches;
                if (contact && !out.closed) {
                    out.closed = true;
                    out.closing_time = t;
                }
                continue;
            }
            y = next;
            t += h;
        }
        return out;
    }

private:
    // min(Kc d, F): the stop pushes while both the penetration d and its force F are positive.
    [[nodiscard]] double switching(const Eigen::VectorXd& y) const {
        const Eigen::Index n = s_.modes;
        const double v = tip_.dot(y.head(n)), rate = tip_.dot(y.tail(n));
        const double d = -s_.stop_gap - v;
        return std::min(s_.stop_stiffness * d, s_.stop_stiffness * d - stop_damping_ * rate);
    }

    // The narrowest air gap over the electrode's span [m] and where it is [x/l].
    [[nodiscard]] std::pair<double, double> narrowest_gap(const Eigen::VectorXd& y) const {
        const Eigen::VectorXd v = shape_ * y.head(s_.modes);
        Eigen::Index at = 0;
        const double lowest = v.minCoeff(&at);
        return {s_.electrode_gap + lowest, xi_[at]};
    }

    [[nodiscard]] Eigen::VectorXd rhs(const Eigen::VectorXd& y, bool contact) const {
        const Eigen::Index n = s_.modes;
        const Eigen::VectorXd q = y.head(n), qd = y.tail(n);
        const Eigen::ArrayXd gap = s_.electrode_gap + (shape_ * q).array();
        const Eigen::VectorXd line_force = -(weight_.array() * pressure_ / (gap * gap)).matrix();
        Eigen::VectorXd force = shape_.transpose() * line_force;
        if (contact) {
            const double v = tip_.dot(q), rate = tip_.dot(qd);
            force += tip_ * (s_.stop_stiffness * (-s_.stop_gap - v) - stop_damping_ * rate);
        }
        Eigen::VectorXd out(2 * n);
        out.head(n) = qd;
        out.tail(n) = force / mass_ - (damping_.array() * qd.array()).matrix() -
                      (omega_.array().square() * q.array()).matrix();
        return out;
    }

    [[nodiscard]] Eigen::VectorXd rk4(const Eigen::VectorXd& y, double h, bool contact) const {
        const Eigen::VectorXd k1 = rhs(y, contact);
        const Eigen::VectorXd k2 = rhs(y + 0.5 * h * k1, contact);
        const Eigen::VectorXd k3 = rhs(y + 0.5 * h * k2, contact);
        const Eigen::VectorXd k4 = rhs(y + h * k3, contact);
        return y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }

    CantileverSwitchSpec s_;
    double mass_ = 0.0, pressure_ = 0.0, stop_damping_ = 0.0;
    Eigen::VectorXd omega_, damping_, xi_, weight_, tip_;
    Eigen::MatrixXd shape_;  // mode shapes at the electrode's quadrature points
};

}  // namespace

SwitchRomRun cantilever_switch_rom(const CantileverSwitchSpec& s, double voltage) {
    if (!(s.modes >= 2 && s.step > 0.0 && s.horizon > 0.0 && s.electrode_gap > 0.0)) {
        throw std::invalid_argument("cantilever_switch_rom: needs two modes, a step, a horizon and a gap");
    }
    return SwitchRom(s, voltage).run();
}

VoltageBracket cantilever_switch_rom_threshold(const CantileverSwitchSpec& s, double lo, double hi, double width) {
    if (cantilever_switch_rom(s, lo).collapsed || !cantilever_switch_rom(s, hi).collapsed) {
        throw std::invalid_argument("cantilever_switch_rom_threshold: the bracket must hold at lo and collapse at hi");
    }
    // Bounded: the bracket halves each time.
    while (hi - lo > width) {
        const double mid = 0.5 * (lo + hi);
        (cantilever_switch_rom(s, mid).collapsed ? hi : lo) = mid;
    }
    return {lo, hi};
}

}  // namespace vi
