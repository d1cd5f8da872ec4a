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
