#include "dynamics/event_search.hpp"

#include <cmath>
#include <limits>
#include <queue>
#include <vector>

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
    double fp = f.derivative(tau, 1);
    while (tau < tau_max) {
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
        const auto [fn, fpn] = f.value_and_slope(next);
        if (evals) ++*evals;
        if (fn > 0.0) return refine(f, tau, next, fv, fn, opt.t_tol, evals);
        tau = next;
        fv = fn;
        fp = fpn;
    }
    return std::nullopt;
}

}  // namespace vi

namespace vi {
namespace {

// Per-mode constants of a signal for repeated bounds: amplitude, |lambda|, |lambda|^2, Re lambda.
struct PreparedModes {
    std::vector<double> amp, mag, mag2, decay;
    explicit PreparedModes(const ExpSignal& f) {
        const Eigen::VectorXcd& lam = *f.lambda;
        for (Eigen::Index k = 0; k < f.A.size(); ++k) {
            const double m = std::abs(lam[k]);
            amp.push_back(std::abs(f.A[k]));
            mag.push_back(m);
            mag2.push_back(m * m);
            decay.push_back(lam[k].real());
        }
    }
};

// Upper bound of f on [a, a + h]: modes slow on this interval enter through a Taylor bound with
// their f(a), f'(a) and |f''|; fast ones (|lambda| h > 2) only through their amplitude.
double upper_bound_on(const ExpSignal& f, const PreparedModes& pm, double a, double h) {
    double f0 = 0.0, f1 = 0.0, b2 = 0.0, fast = 0.0;
    const Eigen::VectorXcd& lam = *f.lambda;
    const std::size_t n = pm.amp.size();
    for (std::size_t k = 0; k < n; ++k) {
        const double re = pm.decay[k];
        // max of exp(re t) over [a, a + h]: at a when decaying (the usual case).
        const double grow = std::exp(re * (re <= 0.0 ? a : a + h));
        const double amp = pm.amp[k] * grow;
        if (pm.mag[k] * h > 2.0) {
            fast += amp;
        } else {
            const cd l = lam[static_cast<Eigen::Index>(k)];
            const double e0 = std::exp(re * a);
            const double ph = l.imag() * a;
            const cd v = f.A[static_cast<Eigen::Index>(k)] * cd(e0 * std::cos(ph), e0 * std::sin(ph));
            f0 += v.real();
            f1 += (v * l).real();
            b2 += amp * pm.mag2[k];
        }
    }
    if (!f.terms.empty()) {
        ExpSignal part;  // the particular terms alone, with no homogeneous amplitudes
        part.lambda = f.lambda;
        part.terms = f.terms;
        f0 += part.derivative(a, 0);
        f1 += part.derivative(a, 1);
        b2 += part.bound(a, h, 2);
    }
    return f0 + std::max(0.0, f1 * h + 0.5 * b2 * h * h) + fast;
}

}  // namespace

SignalMaximum global_maximum(const ExpSignal& f, double tau_end, double abs_tol, double h_min, int* evals,
                             double floor) {
    SignalMaximum best{floor, -1.0};
    auto consider = [&](double tau) {
        const double v = f.value(tau);
        if (evals) ++*evals;
        if (v > best.value) best = {v, tau};
    };
    consider(0.0);
    consider(tau_end);
    // Best first: always refine the interval with the highest upper bound; once that bound cannot
    // beat the best value seen, no interval can, and the search ends.
    struct Interval {
        double bound, a, h;
        bool operator<(const Interval& o) const { return bound < o.bound; }
    };
    const PreparedModes pm(f);
    std::priority_queue<Interval> queue;
    queue.push({upper_bound_on(f, pm, 0.0, tau_end), 0.0, tau_end});
    for (int guard = 0; !queue.empty() && guard < 2000000; ++guard) {
        const Interval iv = queue.top();
        queue.pop();
        if (iv.bound <= best.value + abs_tol) break;
        const double half = 0.5 * iv.h;
        const double mid = iv.a + half;
        consider(mid);
        if (half < h_min) continue;
        for (const double a : {iv.a, mid}) {
            const double b = upper_bound_on(f, pm, a, half);
            if (evals) ++*evals;
            if (b > best.value + abs_tol) queue.push({b, a, half});
        }
    }
    return best;
}

}  // namespace vi
