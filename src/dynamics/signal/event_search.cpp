#include "dynamics/signal/event_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dynamics/signal/signal_scan.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

// Illinois-modified regula falsi on a bracket with f(a) <= 0 < f(b).
double refine(const SignalScan& f, double a, double b, double fa, double fb, double t_tol, int* evals) {
    int side = 0;
    for (int it = 0; it < 200 && b - a > t_tol; ++it) {
        double c = (a * fb - b * fa) / (fb - fa);
        if (!(c > a && c < b)) c = 0.5 * (a + b);
        if (!(c > a && c < b)) break;  // a and b are adjacent doubles
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

// An interval of a branch and bound over a signal, with an upper bound of the signal on it; the
// heaps keep the highest bound on top.
struct Interval {
    double bound;
    ScanPoint a, b;
    bool operator<(const Interval& o) const { return bound < o.bound; }
};

}  // namespace

void charge_evaluations(long* budget, long n) {
    if (!budget) return;
    // The stop flag costs an atomic load; checked once every 256 evaluations (microseconds apart).
    if ((*budget & 255) < n) check_run();
    *budget -= n;
    if (*budget < 0) {
        throw WorkLimitReached("the event and extremum searches used up solver.max_steps evaluations (raise "
                               "solver.max_steps, or coarsen solver.min_search_step)");
    }
}

std::optional<double> first_upcrossing(const ExpSignal& f, double tau0, double tau_max, const CrossingSearch& opt,
                                       int* evals, UnprovenSteps* unproven) {
    SignalScan scan(f, 1.0, tau_max);
    if (!(scan.size() > 0.0)) return std::nullopt;
    double tau = tau0;
    ScanPoint p = scan.evaluate(tau);
    double fv = p.value;
    // Roundoff floor of f: the size of its terms times a few ulps.
    const double noise = 64.0 * std::numeric_limits<double>::epsilon() * p.abs0;
    if (std::abs(fv) <= noise) fv = 0.0;
    bool first = true;
    double fp = p.slope;
    while (tau < tau_max) {
        if (evals) ++*evals;
        charge_evaluations(opt.budget);
        if (fv > 0.0) return tau;  // already positive (caller's state was inconsistent by more than roundoff)
        if (fv == 0.0 && fp > 0.0 && !first) return tau;
        if (fv == 0.0 && fp > 0.0 && first) {
            // At a switching instant f = 0 and rising: the crossing is now, unless f' is roundoff.
            const double fp_noise = 64.0 * std::numeric_limits<double>::epsilon() * p.abs1;
            if (fp > fp_noise) return tau;
        }
        first = false;
        double h = scan.certified_step(p, tau_max - tau, fv);
        const bool forced = !(h >= opt.h_min);
        if (forced) h = opt.h_min;
        // At least one ulp forward: far into a long piece tau + h_min may round back to tau.
        const double next = std::min(std::max(tau + h, std::nextafter(tau, tau_max)), tau_max);
        const ScanPoint before = p;
        if (!forced) scan.clear();  // a forced step keeps the point before it, to bound f over the step
        p = scan.evaluate(next);
        if (evals) ++*evals;
        if (p.value > 0.0) return refine(scan, tau, next, fv, p.value, opt.t_tol, evals);
        if (forced) {
            const double bound = scan.upper_bound(before, p) + scan.roundoff(before);
            if (unproven && bound > 0.0) {
                ++unproven->count;
                unproven->excess = std::max(unproven->excess, bound / scan.size());
            }
            scan.keep_only(p);
        }
        tau = next;
        fv = p.value;
        fp = p.slope;
    }
    return std::nullopt;
}

SignalMaximum global_maximum(const ExpSignal& f, double tau_end, double size_tol, double rel_tol, double h_min,
                             int* evals, double floor, double sign, long* budget) {
    SignalScan scan(f, sign, tau_end);
    const double abs_tol = size_tol * scan.size();
    SignalMaximum best{floor, -1.0};
    double margin = std::max(abs_tol, rel_tol * std::abs(floor));
    auto consider = [&](const ScanPoint& p) {
        if (evals) ++*evals;
        if (p.value > best.value) {
            best = {p.value, p.t};
            margin = std::max(abs_tol, rel_tol * std::abs(best.value));
        }
    };
    // Best first: always refine the interval with the highest upper bound; once that bound cannot
    // beat the best value seen, no interval can, and the search ends. The heap holds the bound and
    // the indices of the ends in `points` (moving whole points about the heap cost more).
    struct Span {
        double bound;
        int a, b;
        bool operator<(const Span& o) const { return bound < o.bound; }
    };
    thread_local std::vector<Span> heap;
    thread_local std::vector<ScanPoint> points;
    heap.clear();
    points.clear();
    // Without a run's budget, a bound of its own: no search runs without a limit on its work.
    long own_budget = 6000000;
    if (!budget) budget = &own_budget;
    points.push_back(scan.evaluate(0.0));
    points.push_back(scan.evaluate(tau_end));
    consider(points[0]);
    consider(points[1]);
    heap.push_back({scan.upper_bound(points[0], points[1]), 0, 1});
    while (!heap.empty()) {
        charge_evaluations(budget, 3);
        std::pop_heap(heap.begin(), heap.end());
        const Span iv = heap.back();
        heap.pop_back();
        if (iv.bound <= best.value + margin) break;
        const double half = 0.5 * (points[static_cast<std::size_t>(iv.b)].t - points[static_cast<std::size_t>(iv.a)].t);
        points.push_back(scan.evaluate(points[static_cast<std::size_t>(iv.a)].t + half));
        const int mid = static_cast<int>(points.size()) - 1;
        consider(points.back());
        if (half < h_min) continue;
        for (const auto& [a, b] : {std::pair{iv.a, mid}, std::pair{mid, iv.b}}) {
            const double bound = scan.upper_bound(points[static_cast<std::size_t>(a)], points[static_cast<std::size_t>(b)]);
            if (evals) ++*evals;
            if (bound > best.value + margin) {
                heap.push_back({bound, a, b});
                std::push_heap(heap.begin(), heap.end());
            }
        }
    }
    return best;
}

LevelComparison compare_with_level(const ExpSignal& f, double tau_end, double level, double size_tol, double rel_tol,
                                   double h_min, int* evals, long* budget) {
    SignalScan scan(f, 1.0, tau_end);
    const double certain = level + 2.0 * (rel_tol * std::abs(level) + size_tol * scan.size());
    LevelComparison out;
    // A value proves the maximum above the level only beyond the margin global_maximum may leave.
    auto settles_above = [&](const ScanPoint& p) {
        if (evals) ++*evals;
        out.seen = std::max(out.seen, p.value);
        return p.value - SignalScan::roundoff(p) > certain;
    };
    auto bound = [&](const ScanPoint& a, const ScanPoint& b) {
        if (evals) ++*evals;
        return scan.upper_bound(a, b) + std::max(SignalScan::roundoff(a), SignalScan::roundoff(b));
    };
    auto decided = [&](LevelComparison::Outcome o) {
        out.outcome = o;
        return out;
    };
    long own_budget = 6000000;
    if (!budget) budget = &own_budget;
    const ScanPoint p0 = scan.evaluate(0.0);
    const ScanPoint p1 = scan.evaluate(tau_end);
    if (settles_above(p0) || settles_above(p1)) return decided(LevelComparison::above);
    // A value above the level but within the margin: only the full search can tell.
    if (out.seen > level) return decided(LevelComparison::undecided);
    std::vector<Interval> heap{{bound(p0, p1), p0, p1}};
    // Highest bound first: a value above the level, if there is one, is met soonest there. Only
    // intervals bounded above the level are kept.
    while (!heap.empty() && heap.front().bound > level) {
        charge_evaluations(budget, 3);
        std::pop_heap(heap.begin(), heap.end());
        const Interval iv = heap.back();
        heap.pop_back();
        const double half = 0.5 * (iv.b.t - iv.a.t);
        if (half < h_min) return decided(LevelComparison::undecided);
        const ScanPoint mid = scan.evaluate(iv.a.t + half);
        if (settles_above(mid)) return decided(LevelComparison::above);
        if (out.seen > level) return decided(LevelComparison::undecided);
        for (const auto& [a, b] : {std::pair{iv.a, mid}, std::pair{mid, iv.b}}) {
            const double ub = bound(a, b);
            if (ub > level) {
                heap.push_back({ub, a, b});
                std::push_heap(heap.begin(), heap.end());
            }
        }
    }
    return decided(LevelComparison::below);
}

}  // namespace vi
