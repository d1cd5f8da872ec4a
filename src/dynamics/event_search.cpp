#include "dynamics/event_search.hpp"

#include <cmath>
#include <limits>

namespace vi {
namespace {

// Illinois-modified regula falsi on a bracket with f(a) <= 0 < f(b).
double refine(const ExpSignal& f, double a, double b, double fa, double fb, double t_tol, int* evals) {
    int side = 0;
    for (int it = 0; it < 200 && b - a > t_tol; ++it) {
        double c = (a * fb - b * fa) / (fb - fa);
        if (!(c > a && c < b)) c = 0.5 * (a + b);
        const double fc = f.value(c);
        if (evals) ++*evals;
        if (fc > 0) {
            b = c;
            fb = fc;
            if (side == -1) fa *= 0.5;
            side = -1;
        } else {
            a = c;
            fa = fc;
            if (side == 1) fb *= 0.5;
            side = 1;
        }
    }
    return b;
}

}  // namespace

std::optional<double> first_upcrossing(const ExpSignal& f, double tau0, double tau_max, const CrossingSearch& opt,
                                       int* evals) {
    double tau = tau0;
    double fv = f.value(tau);
    // Roundoff floor of f: the size of its terms times a few ulps.
    const double noise = 64.0 * std::numeric_limits<double>::epsilon() * f.bound(tau0, 0.0, 0);
    if (std::abs(fv) <= noise) fv = 0.0;
    bool first = true;
    while (tau < tau_max) {
        const double fp = f.derivative(tau, 1);
        if (evals) ++*evals;
        if (fv > 0.0) return tau;  // already positive (caller's state was inconsistent by more than roundoff)
        if (fv == 0.0 && fp > 0.0 && !first) return tau;
        if (fv == 0.0 && fp > 0.0 && first) {
            // At a switching instant f = 0 and rising: the crossing is now, unless f' is roundoff.
            const double fp_noise = 64.0 * std::numeric_limits<double>::epsilon() * f.bound(tau, 0.0, 1);
            if (fp > fp_noise) return tau;
        }
        first = false;
        const double B = f.bound(tau, tau_max - tau, 2);
        double h;
        if (B > 0.0) {
            const double disc = fp * fp - 2.0 * B * fv;  // fv <= 0
            h = (-fp + std::sqrt(std::max(disc, 0.0))) / B;
        } else {
            h = fp > 0.0 ? -fv / fp : std::numeric_limits<double>::infinity();
        }
        if (!(h >= opt.h_min)) h = opt.h_min;
        const double next = std::min(tau + h, tau_max);
        const double fn = f.value(next);
        if (evals) ++*evals;
        if (fn > 0.0) return refine(f, tau, next, fv, fn, opt.t_tol, evals);
        tau = next;
        fv = fn;
    }
    return std::nullopt;
}

}  // namespace vi

namespace vi {
namespace {

// Upper bound of f on [a, a + h]: modes slow on this interval enter through a Taylor bound with
// their f(a), f'(a) and |f''|; fast ones (|lambda| h > 2) only through their amplitude.
double upper_bound_on(const ExpSignal& f, double a, double h) {
    double f0 = 0.0, f1 = 0.0, b2 = 0.0, fast = 0.0;
    const Eigen::VectorXcd& lam = *f.lambda;
    for (Eigen::Index k = 0; k < f.A.size(); ++k) {
        const cd l = lam[k];
        const double decay = std::exp(l.real() * a);
        const double amp = std::abs(f.A[k]) * std::max(decay, std::exp(l.real() * (a + h)));
        if (std::abs(l) * h > 2.0) {
            fast += amp;
        } else {
            const cd v = f.A[k] * std::exp(l * a);
            f0 += v.real();
            f1 += (v * l).real();
            b2 += amp * std::norm(l);
        }
    }
    for (const ExpTerm& t : f.terms) {
        ExpSignal one;
        one.lambda = f.lambda;
        one.terms = {t};
        f0 += one.derivative(a, 0);
        f1 += one.derivative(a, 1);
        b2 += one.bound(a, h, 2);
    }
    return f0 + std::max(0.0, f1 * h + 0.5 * b2 * h * h) + fast;
}

}  // namespace

SignalMaximum global_maximum(const ExpSignal& f, double tau_end, double abs_tol, double h_min, int* evals,
                             double floor) {
    SignalMaximum best{floor, -1.0};
    const double f0 = f.value(0.0);
    if (f0 > best.value) best = {f0, 0.0};
    const double fe = f.value(tau_end);
    if (fe > best.value) best = {fe, tau_end};
    struct Interval {
        double a, h;
    };
    std::vector<Interval> stack{{0.0, tau_end}};
    int guard = 0;
    while (!stack.empty() && ++guard < 2000000) {
        const Interval iv = stack.back();
        stack.pop_back();
        if (evals) ++*evals;
        if (upper_bound_on(f, iv.a, iv.h) <= best.value + abs_tol) continue;
        const double half = 0.5 * iv.h;
        const double mid = iv.a + half;
        const double fm = f.value(mid);
        if (fm > best.value) best = {fm, mid};
        if (half < h_min) continue;
        stack.push_back({mid, half});
        stack.push_back({iv.a, half});
    }
    return best;
}

}  // namespace vi
