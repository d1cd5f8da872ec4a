#pragma once
// ExpSignal: a scalar response within one piece of the exact solution, as a sum of exponentials
// f(tau) = Re[ sum_k A_k exp(lambda_k tau) + sum_m c_m tau^p_m exp(s_m tau) ].

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <utility>
#include <vector>

namespace vi {

using cd = std::complex<double>;

// A particular-solution term c tau^power exp(s tau), power 0 or 1.
struct ExpTerm {
    cd coef;
    cd s;
    int power = 0;
};

// d-th derivative of one particular term at tau.
cd term_derivative(const ExpTerm& t, double tau, int d);
// An upper bound of |d-th derivative| of a sum of particular terms over [tau, tau + h] (as
// ExpSignal::bound sums them).
double terms_bound(const std::vector<ExpTerm>& terms, double tau, double h, int d, double b = 0.0);

struct ExpSignal {
    const Eigen::VectorXcd* lambda = nullptr;  // exponents of the homogeneous part [1/s]
    Eigen::VectorXcd A;                        // their amplitudes
    std::vector<ExpTerm> terms;                // particular part (forcing, constants)

    // d-th derivative (0..3) at tau [s].
    [[nodiscard]] double derivative(double tau, int d) const;
    [[nodiscard]] double value(double tau) const { return derivative(tau, 0); }
    // The value given e_k = fast_exp(lambda_k, tau) already computed (one set serves every channel of
    // a piece): the same as value(tau) to the last bit.
    [[nodiscard]] double value(double tau, const Eigen::VectorXcd& e) const;
    // f and f' together (one exponential per mode).
    [[nodiscard]] std::pair<double, double> value_and_slope(double tau) const;
    // An upper bound of |f^(d)| over [tau, tau + h].
    [[nodiscard]] double bound(double tau, double h, int d) const;
    // Integral of f over [0, tau].
    [[nodiscard]] double integral(double tau) const;
    // The same given e_k = fast_exp(lambda_k, tau) already computed: the same value to the last bit.
    [[nodiscard]] double integral(double tau, const Eigen::VectorXcd& e) const;
};

// exp(z tau) as exp(Re) (cos, sin): no complex-library call, and 0 without libm's underflow path once
// |exp(z tau)| < 1e-307 (a heavily damped mode long after its start: below roundoff of any sum).
inline cd fast_exp(cd z, double tau) {
    // At a piece's start every exponential is 1 (what the libm calls below return there too).
    if (tau == 0.0) return cd(1.0, 0.0);
    // A constant term (z = 0): exp(0) = 1 exactly, without the library call.
    if (z.real() == 0.0 && z.imag() == 0.0) return cd(1.0, 0.0);
    const double x = z.real() * tau;
    if (x < -707.0) return cd(0.0, 0.0);
    const double e = std::exp(x);
    if (z.imag() == 0.0) return cd(e, 0.0);
    const double ph = z.imag() * tau;
    return cd(e * std::cos(ph), e * std::sin(ph));
}

// Integral over [0, tau] of t^p exp(mu t) (p = 0, 1, 2), accurate also for small |mu tau|.
cd exp_moment(cd mu, int p, double tau);
// The same given e = exp(mu tau).
cd exp_moment(cd mu, int p, double tau, cd e);

// Integral over [0, tau] of f(t) g(t) for two signals over the same piece.
double product_integral(const ExpSignal& f, const ExpSignal& g, double tau);

}  // namespace vi
