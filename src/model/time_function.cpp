#include "model/time_function.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vi {

double TimeFunction::operator()(double t) const {
    switch (kind) {
        case Kind::constant: return 1.0;
        case Kind::step: return t >= t_on ? 1.0 : 0.0;
        case Kind::harmonic: return offset + std::sin(2.0 * std::numbers::pi * frequency_hz * t + phase);
        case Kind::table: {
            if (times.empty()) return 0.0;
            if (t <= times.front()) return values.front();
            if (t >= times.back()) return values.back();
            const auto it = std::upper_bound(times.begin(), times.end(), t);
            const std::size_t i = static_cast<std::size_t>(it - times.begin());
            const double w = (t - times[i - 1]) / (times[i] - times[i - 1]);
            return values[i - 1] + w * (values[i] - values[i - 1]);
        }
    }
    return 0.0;
}

double TimeFunction::slope(double t) const {
    switch (kind) {
        case Kind::constant:
        case Kind::step: return 0.0;
        case Kind::harmonic: {
            const double w = 2.0 * std::numbers::pi * frequency_hz;
            return w * std::cos(w * t + phase);
        }
        case Kind::table: {
            if (times.size() < 2 || t < times.front() || t >= times.back()) return 0.0;
            const auto it = std::upper_bound(times.begin(), times.end(), t);
            const std::size_t i = static_cast<std::size_t>(it - times.begin());
            return (values[i] - values[i - 1]) / (times[i] - times[i - 1]);
        }
    }
    return 0.0;
}

double TimeFunction::max_abs() const {
    switch (kind) {
        case Kind::constant:
        case Kind::step: return 1.0;
        case Kind::harmonic: return std::abs(offset) + 1.0;
        case Kind::table: {
            double m = 0.0;
            for (double v : values) m = std::max(m, std::abs(v));
            return m;
        }
    }
    return 0.0;
}

namespace {

// A table's knots in (t0, t1) where it leaves the straight line from the previous kept knot by more
// than tol, with its first and last knots: the slopes from the anchor (the last kept knot) that keep
// every knot since it within tol form a cone, narrowed knot by knot; the first knot whose chord
// leaves it ends the straight stretch at the knot before, the next anchor. O(rows).
std::vector<double> corners(const std::vector<double>& times, const std::vector<double>& values, double tol, double t0,
                            double t1) {
    std::vector<double> out;
    const auto keep = [&](std::size_t i) {
        if (times[i] > t0 && times[i] < t1 && (out.empty() || out.back() != times[i])) out.push_back(times[i]);
    };
    const std::size_t n = times.size();
    if (n == 0) return out;
    keep(0);
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::size_t a = 0;
    double lo = -inf, hi = inf;
    for (std::size_t i = 1; i < n && times[a] < t1; ++i) {
        double dt = times[i] - times[a];
        const double s = (values[i] - values[a]) / dt;
        if (s < lo || s > hi) {
            a = i - 1;
            keep(a);
            lo = -inf;
            hi = inf;
            dt = times[i] - times[a];
        }
        lo = std::max(lo, (values[i] - tol - values[a]) / dt);
        hi = std::min(hi, (values[i] + tol - values[a]) / dt);
    }
    keep(n - 1);
    return out;
}

}  // namespace

std::vector<double> TimeFunction::breakpoints(double t0, double t1) const {
    if (kind == Kind::step) return t_on > t0 && t_on < t1 ? std::vector<double>{t_on} : std::vector<double>{};
    if (kind != Kind::table) return {};
    return corners(times, values, kTableExactTolerance * max_abs(), t0, t1);
}

std::vector<double> TimeFunction::stops(double t0, double t1) const {
    if (kind == Kind::step) return t_on > t0 && t_on < t1 ? std::vector<double>{t_on} : std::vector<double>{};
    if (kind != Kind::table) return {};
    return corners(times, values, kTableStopTolerance * max_abs(), t0, t1);
}

}  // namespace vi
