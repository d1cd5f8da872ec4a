#include "dynamics/signal/exp_signal.hpp"

#include <algorithm>
#include <cmath>

namespace vi {

cd term_derivative(const ExpTerm& t, double tau, int d) {
    const cd e = fast_exp(t.s, tau);
    if (t.power == 0) return t.coef * std::pow(t.s, d) * e;
    // d^d/dtau^d (tau e^{s tau}) = (s^d tau + d s^(d-1)) e^{s tau}
    const cd lower = d == 0 ? cd(0.0) : static_cast<double>(d) * std::pow(t.s, d - 1);
    return t.coef * (std::pow(t.s, d) * tau + lower) * e;
}

std::pair<double, double> ExpSignal::value_and_slope(double tau) const {
    cd v = 0.0, s = 0.0;
    for (Eigen::Index k = 0; k < A.size(); ++k) {
        const cd l = (*lambda)[k];
        const cd f = A[k] * fast_exp(l, tau);
        v += f;
        s += f * l;
    }
    for (const ExpTerm& t : terms) {
        v += term_derivative(t, tau, 0);
        s += term_derivative(t, tau, 1);
    }
    return {v.real(), s.real()};
}

double ExpSignal::value(double tau, const Eigen::VectorXcd& e) const {
    // Summed in derivative()'s order: the same value to the last bit.
    cd sum = 0.0;
    for (Eigen::Index k = 0; k < A.size(); ++k) sum += A[k] * e[k];
    for (const ExpTerm& t : terms) sum += term_derivative(t, tau, 0);
    return sum.real();
}

double ExpSignal::derivative(double tau, int d) const {
    cd sum = 0.0;
    for (Eigen::Index k = 0; k < A.size(); ++k) {
        const cd l = (*lambda)[k];
        cd f = A[k] * fast_exp(l, tau);
        for (int i = 0; i < d; ++i) f *= l;
        sum += f;
    }
    for (const ExpTerm& t : terms) sum += term_derivative(t, tau, d);
    return sum.real();
}

double ExpSignal::bound(double tau, double h, int d) const {
    double b = 0.0;
    for (Eigen::Index k = 0; k < A.size(); ++k) {
        const cd l = (*lambda)[k];
        // max of exp(Re l t) over [tau, tau + h]: at tau for a decaying mode.
        const double x = l.real() * (l.real() <= 0.0 ? tau : tau + h);
        // Below exp(-707) the term is under 1e-307 of its amplitude: bounded by that, no libm slow path.
        const double growth = x == 0.0 ? 1.0 : x < -707.0 ? 1e-307 : std::exp(x);
        const double mag2 = std::norm(l);
        double m = 1.0;
        if (d == 1) m = std::sqrt(mag2);
        if (d == 2) m = mag2;
        if (d >= 3) m = std::pow(mag2, 0.5 * d);
        b += std::sqrt(std::norm(A[k])) * m * growth;
    }
    return terms_bound(terms, tau, h, d, b);
}

double terms_bound(const std::vector<ExpTerm>& terms, double tau, double h, int d, double b) {
    for (const ExpTerm& t : terms) {
        const double growth = std::max(std::exp(t.s.real() * tau), std::exp(t.s.real() * (tau + h)));
        const double as = std::abs(t.s);
        double m = std::pow(as, d);
        if (t.power == 1) m = m * (tau + h) + (d == 0 ? 0.0 : d * std::pow(as, d - 1));
        b += std::abs(t.coef) * m * growth;
    }
    return b;
}

cd exp_moment(cd mu, int p, double tau) { return exp_moment(mu, p, tau, fast_exp(mu, tau)); }

cd exp_moment(cd mu, int p, double tau, cd e) {
    const cd x = mu * tau;
    if (std::abs(x) < 0.1) {
        // Series: tau^(p+1) sum_n x^n / (n! (n + p + 1)).
        cd sum = 0.0, term = 1.0;
        for (int n = 0; n < 30; ++n) {
            sum += term / static_cast<double>(n + p + 1);
            term *= x / static_cast<double>(n + 1);
        }
        return sum * std::pow(tau, p + 1);
    }
    const cd i0 = (e - 1.0) / mu;
    if (p == 0) return i0;
    const cd i1 = (tau * e - i0) / mu;
    if (p == 1) return i1;
    return (tau * tau * e - 2.0 * i1) / mu;
}

double ExpSignal::integral(double tau) const {
    cd sum = 0.0;
    for (Eigen::Index k = 0; k < A.size(); ++k) sum += A[k] * exp_moment((*lambda)[k], 0, tau);
    for (const ExpTerm& t : terms) sum += t.coef * exp_moment(t.s, t.power, tau);
    return sum.real();
}

double ExpSignal::integral(double tau, const Eigen::VectorXcd& e) const {
    cd sum = 0.0;
    for (Eigen::Index k = 0; k < A.size(); ++k) sum += A[k] * exp_moment((*lambda)[k], 0, tau, e[k]);
    for (const ExpTerm& t : terms) sum += t.coef * exp_moment(t.s, t.power, tau);
    return sum.real();
}

double product_integral(const ExpSignal& f, const ExpSignal& g, double tau) {
    // Re(a) Re(b) = (a b + a conj(b)) / 2: both products are sums of exponentials.
    cd sum = 0.0;
    auto pair = [&](cd ca, cd ma, int pa, cd cb, cd mb, int pb) {
        sum += 0.5 * ca * cb * exp_moment(ma + mb, pa + pb, tau);
        sum += 0.5 * ca * std::conj(cb) * exp_moment(ma + std::conj(mb), pa + pb, tau);
    };
    for (Eigen::Index k = 0; k < f.A.size(); ++k) {
        const cd lk = (*f.lambda)[k];
        for (Eigen::Index l = 0; l < g.A.size(); ++l) pair(f.A[k], lk, 0, g.A[l], (*g.lambda)[l], 0);
        for (const ExpTerm& t : g.terms) pair(f.A[k], lk, 0, t.coef, t.s, t.power);
    }
    for (const ExpTerm& t : f.terms) {
        for (Eigen::Index l = 0; l < g.A.size(); ++l) pair(t.coef, t.s, t.power, g.A[l], (*g.lambda)[l], 0);
        for (const ExpTerm& u : g.terms) pair(t.coef, t.s, t.power, u.coef, u.s, u.power);
    }
    return sum.real();
}

}  // namespace vi
