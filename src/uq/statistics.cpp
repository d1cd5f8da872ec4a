#include "uq/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>

#include "uq/sampling.hpp"

namespace vi {

double sample_mean(const std::vector<double>& x) {
    double s = 0.0;
    for (double v : x) s += v;
    return x.empty() ? std::nan("") : s / static_cast<double>(x.size());
}

double sample_std(const std::vector<double>& x) {
    if (x.size() < 2) return 0.0;
    const double m = sample_mean(x);
    double s = 0.0;
    for (double v : x) s += (v - m) * (v - m);
    return std::sqrt(s / static_cast<double>(x.size() - 1));
}

double sorted_quantile(const std::vector<double>& sorted, double p) {
    if (sorted.empty()) return std::nan("");
    const double h = (static_cast<double>(sorted.size()) - 1.0) * p;
    const std::size_t lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

std::optional<Interval> quantile_interval(const std::vector<double>& sorted, double p, double confidence) {
    const std::size_t n = sorted.size();
    if (n == 0) return std::nullopt;
    // B, the count of values below the p-quantile, is binomial(n, p). [x_(l), x_(u)] (ranks from 1)
    // covers it when l <= B <= u - 1: probability F(u - 1) - F(l - 1).
    const boost::math::binomial_distribution<double> b(static_cast<double>(n), p);
    const double tail = 0.5 * (1.0 - confidence);
    const auto below = [&](std::size_t k) { return boost::math::cdf(b, static_cast<double>(k)); };
    const auto above = [&](std::size_t k) { return boost::math::cdf(boost::math::complement(b, static_cast<double>(k))); };
    // l: the largest rank with F(l - 1) <= tail (0 when even F(0) is above it), by bisection on the
    // monotone F; u: the smallest rank with 1 - F(u - 1) <= tail (n + 1 when none is).
    std::size_t lo = 0, hi = n;  // F(lo - 1) <= tail holds at lo = 0
    while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        if (below(mid - 1) <= tail) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    const std::size_t l = lo;
    lo = 1;
    hi = n + 1;  // 1 - F(hi - 1) <= tail holds at hi = n + 1 (F(n) = 1)
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (above(mid - 1) <= tail) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    const std::size_t u = hi;
    if (l < 1 || u > n) return std::nullopt;
    return Interval{sorted[l - 1], sorted[u - 1]};
}

std::optional<Interval> mean_interval(const std::vector<double>& x, double confidence) {
    if (x.size() < 2) return std::nullopt;
    const boost::math::students_t t(static_cast<double>(x.size() - 1));
    const double half = boost::math::quantile(t, 0.5 + 0.5 * confidence) * sample_std(x) /
                        std::sqrt(static_cast<double>(x.size()));
    const double m = sample_mean(x);
    return Interval{m - half, m + half};
}

std::optional<Interval> bootstrap_interval(std::size_t n, std::size_t resamples, std::uint64_t seed, double confidence,
                                           const std::function<double(const std::vector<std::size_t>&)>& statistic) {
    if (n == 0 || resamples == 0) return std::nullopt;
    UnitRandom random(seed);
    std::vector<std::size_t> rows(n);
    std::vector<double> values;
    values.reserve(resamples);
    for (std::size_t r = 0; r < resamples; ++r) {
        for (std::size_t& i : rows) i = random.below(n);
        const double v = statistic(rows);
        if (!std::isnan(v)) values.push_back(v);
    }
    if (2 * values.size() < resamples) return std::nullopt;
    std::sort(values.begin(), values.end());
    return Interval{sorted_quantile(values, 0.5 * (1.0 - confidence)), sorted_quantile(values, 0.5 * (1.0 + confidence))};
}

std::uint64_t derived_seed(std::uint64_t seed, std::uint64_t purpose) {
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (purpose + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

}  // namespace vi
