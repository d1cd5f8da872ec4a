#include "validation/closed_forms.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "model/bisection.hpp"

namespace vi::closed_form {
namespace {

// The first n sign changes of f on (lo, hi) scanned with step h, each refined by bisection.
std::vector<double> roots(const std::function<double(double)>& f, double lo, double hi, double h, int n) {
    std::vector<double> r;
    double a = lo;
    double fa = f(a);
    while (static_cast<int>(r.size()) < n && a < hi) {
        const double b = std::min(a + h, hi);
        const double fb = f(b);
        if (fa != 0.0 && (fa < 0) != (fb < 0)) r.push_back(bisect_sign_change(f, a, b));
        a = b;
        fa = fb;
    }
    return r;
}

}  // namespace

std::vector<double> cantilever_beta_l(int n) {
    // cos x + 1/cosh x = 0 is the well-scaled form of cos x cosh x = -1.
    return roots([](double x) { return std::cos(x) + 1.0 / std::cosh(x); }, 0.5, 4.0 * n + 4.0, 1e-2, n);
}

std::vector<double> clamped_clamped_beta_l(int n) {
    return roots([](double x) { return std::cos(x) - 1.0 / std::cosh(x); }, 1.0, 4.0 * n + 4.0, 1e-2, n);
}

double bending_omega(double beta_l, double E, double I, double rho, double A, double l) {
    return beta_l * beta_l * std::sqrt(E * I / (rho * A * l * l * l * l));
}

double cantilever_shape(double b, double s) {
    const double sigma = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
    const double x = b * s;
    return std::cosh(x) - std::cos(x) - sigma * (std::sinh(x) - std::sin(x));
}

double cantilever_slope(double b, double s) {
    const double sigma = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
    const double x = b * s;
    return b * (std::sinh(x) + std::sin(x) - sigma * (std::cosh(x) - std::cos(x)));
}

std::vector<double> cantilever_shape_zeros(double b) {
    return roots([b](double s) { return cantilever_shape(b, s); }, 1e-3, 1.0, 1e-3, 100);
}

std::vector<double> cantilever_slope_zeros(double b) {
    return roots([b](double s) { return cantilever_slope(b, s); }, 1e-3, 1.0, 1e-3, 100);
}

double pinned_cantilever_beta_l(double a) {
    if (!(a > 0.0 && a <= 1.0)) throw std::invalid_argument("pinned_cantilever_beta_l: a must lie in (0, 1]");
    // Span 1 on [0, a] in s, span 2 on [a, 1] in the local r = s - a; each
    // w = c0 cosh(k .) + c1 sinh(k .) + c2 cos(k .) + c3 sin(k .), k = beta l. Derivatives to order 3.
    auto row = [](double k, double s, int d) {
        Eigen::Matrix<double, 1, 4> r;
        const double ch = std::cosh(k * s), sh = std::sinh(k * s), c = std::cos(k * s), sn = std::sin(k * s);
        const double p = std::pow(k, d);
        switch (d) {
            case 0: r << ch, sh, c, sn; break;
            case 1: r << sh, ch, -sn, c; break;
            case 2: r << ch, sh, -c, -sn; break;
            default: r << sh, ch, sn, -c; break;
        }
        return Eigen::Matrix<double, 1, 4>(r * p);
    };
    const double b_len = 1.0 - a;
    auto det = [&](double k) {
        if (b_len <= 0.0) {
            // Propped cantilever: clamped at 0, pinned at 1.
            Eigen::Matrix4d m;
            m.row(0) = row(k, 0.0, 0);
            m.row(1) = row(k, 0.0, 1);
            m.row(2) = row(k, 1.0, 0);
            m.row(3) = row(k, 1.0, 2);
            return m.determinant() / std::pow(std::cosh(k), 2);
        }
        Eigen::Matrix<double, 8, 8> m = Eigen::Matrix<double, 8, 8>::Zero();
        m.block<1, 4>(0, 0) = row(k, 0.0, 0);             // w1(0) = 0
        m.block<1, 4>(1, 0) = row(k, 0.0, 1);             // w1'(0) = 0
        m.block<1, 4>(2, 0) = row(k, a, 0);               // w1(a) = 0
        m.block<1, 4>(3, 4) = row(k, 0.0, 0);             // w2(a) = 0
        m.block<1, 4>(4, 0) = row(k, a, 1);               // slope continuous
        m.block<1, 4>(4, 4) = -row(k, 0.0, 1);
        m.block<1, 4>(5, 0) = row(k, a, 2);               // moment continuous
        m.block<1, 4>(5, 4) = -row(k, 0.0, 2);
        m.block<1, 4>(6, 4) = row(k, b_len, 2);           // free end: no moment
        m.block<1, 4>(7, 4) = row(k, b_len, 3);           // free end: no shear
        return m.determinant() / (std::pow(std::cosh(k * a), 2) * std::pow(std::cosh(k * b_len), 2));
    };
    const std::vector<double> r = roots(det, 0.3, 40.0, 1e-3, 1);
    if (r.empty()) throw std::runtime_error("pinned_cantilever_beta_l: no root found");
    return r.front();
}

}  // namespace vi::closed_form
