#pragma once
// Rigorous local bounds of an ExpSignal for the certified event search and the branch-and-bound
// maxima: from one evaluation at t, upper bounds of f over [t, t + h] for every split of its modes
// into slow ones (Taylor with exact value and slope) and fast ones (amplitude only).

#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "dynamics/signal/exp_signal.hpp"

namespace vi {

// One evaluation point: exact-arithmetic estimates and, over its live modes in ascending |lambda|,
// prefix sums indexed by the number J of slow modes (0..live). Modes too small to matter are not
// evaluated (no sin/cos); their magnitude or a bound of it still enters every bound (f0, f1 as
// +-|v|, mag, b2). Modes past their death time (below the skip threshold for good) are not live:
// they are always counted among the fast modes, each by the threshold.
struct ScanPoint {
    double t = 0.0;
    double value = 0.0;   // f(t), skipped modes left out (each below 1e-18 of the signal's size)
    double slope = 0.0;   // f'(t), likewise
    double abs0 = 0.0;    // sum |v_k| + |particular part|: the roundoff scale of f(t)
    double abs1 = 0.0;    // sum |lambda_k v_k| + |particular slope|: the roundoff scale of f'(t)
    double p0 = 0.0;      // particular part's value and slope at t
    double p1 = 0.0;
    int live = 0;            // modes not yet dead
    double dead_mag = 0.0;   // bound of the dead modes' sum |v_k|
    std::size_t offset = 0;  // where its prefix records live in the scan's store
};

// What a scan keeps of one exponent lambda.
struct SignalScanPole {
    double re, im, mag, mag2;  // lambda, |lambda|, |lambda|^2 [1/s, 1/s^2]
};
struct PoleSet;

class SignalScan {
public:
    // sign = -1 scans -f (for minima). t_end: the particular part's |f''| is bounded over [0, t_end].
    SignalScan(const ExpSignal& f, double sign, double t_end);
    ~SignalScan();
    SignalScan(const SignalScan&) = delete;
    SignalScan& operator=(const SignalScan&) = delete;
    // Evaluates at t and keeps the point's prefix sums (until clear()).
    ScanPoint evaluate(double t);
    // Only the value (for root refinement).
    [[nodiscard]] double value(double t) const;
    void clear() { used_ = 0; }
    // Drops every point's records but p's (which stays valid).
    void keep_only(ScanPoint& p);
    // The longest h <= H such that f < 0 on [p.t, p.t + h] is proven by some slow/fast split, taking
    // the value at p.t as `value_used` (the caller may set a value within roundoff of 0 to 0);
    // 0 when no split proves any step.
    [[nodiscard]] double certified_step(const ScanPoint& p, double H, double value_used) const;
    // An upper bound of f on [a.t, b.t]: the smaller of a Taylor bound from a and a bound by
    // interpolation between a and b plus |f''| (b.t - t)(t - a.t) / 2, over the slow modes of that length.
    [[nodiscard]] double upper_bound(const ScanPoint& a, const ScanPoint& b) const;
    // A bound of the rounding error of p's value as summed here (each term to a few ulps, the sum
    // of `live` terms to live ulps of sum |terms|); certified_step adds it to its bounds.
    [[nodiscard]] static double roundoff(const ScanPoint& p);
    [[nodiscard]] int modes() const { return m_; }
    [[nodiscard]] double size() const { return size_; }

private:
    // The prefix record of point p with J slow modes: {f0, f1, mag, b2, |lambda| of live mode J}.
    static constexpr int kRecord = 5;
    const double* record(const ScanPoint& p, int J) const {
        return store_.get() + p.offset + static_cast<std::size_t>(kRecord * J);
    }
    int slow_count(const ScanPoint& p, double h) const;
    // The modes not dead at t (live_, in mode order) and what the dead ones add to the bounds;
    // kept while t stays between the same death times.
    void update_live(double t) const;
    // exp(Re lambda t), then cos and sin of Im lambda t, of the live modes (after update_live(t)):
    // three arrays of live_.size() values, in the thread's scratch until the next call.
    const double* exponentials(double t) const;
    double growth(double h) const;

    int m_ = 0;
    struct Mode {
        cd A;        // amplitude (times sign)
        double amp;  // |A|
    };
    std::vector<Mode> modes_;            // ascending |lambda|
    static std::vector<Mode>& spare_modes();
    // The exponents' part, shared by the scans of signals with the same exponents.
    std::shared_ptr<const PoleSet> pole_set_;
    const SignalScanPole* poles_ = nullptr;  // ascending |lambda|
    const double* mags_ = nullptr;           // their |lambda|, contiguous
    std::vector<ExpTerm> terms_;         // particular part (times sign)
    double terms_b2_ = 0.0;              // bound of |particular''| over [0, t_end]
    double gamma_ = 0.0;                 // largest Re lambda > 0 (roundoff of undamped modes), else 0
    double size_ = 0.0;                  // sum |A_k| + sum |term coef|
    double skip_ = 0.0;                  // |v_k| below this: not evaluated
    // Prefix sums of the points, uninitialised and reused across scans of one thread (a B&B keeps
    // thousands of points; zeroing or page-faulting fresh buffers cost more than the sums).
    std::unique_ptr<double[]> store_;
    std::size_t capacity_ = 0, used_ = 0;
    std::vector<double> dead_;  // each mode's death time (from it on |v_k| <= skip_: no evaluation at all)
    // Per block of kBlock consecutive modes: {earliest death time, latest, sum of |lambda|}.
    static constexpr int kBlock = 8;
    std::vector<double> blocks_;
    mutable std::vector<int> live_;
    mutable double live_from_ = 0.0, live_until_ = -1.0;  // live_ holds for t in [from, until)
    mutable int dead_count_ = 0;
    mutable double dead_abs1_ = 0.0;  // sum over the dead modes of skip_ |lambda_k|
};

}  // namespace vi
