#pragma once
// Estimates from a sample of one quantity and their confidence intervals: mean (Student's t),
// standard deviation (bootstrap), quantiles (order statistics, distribution-free); docs/uq.md.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace vi {

// A confidence interval [low, high].
struct Interval {
    double low = 0.0, high = 0.0;
};

double sample_mean(const std::vector<double>& x);
// With n - 1 in the denominator; 0 for fewer than two values.
double sample_std(const std::vector<double>& x);

// The p-quantile (0 <= p <= 1) of sorted values by linear interpolation between order statistics
// (Hyndman and Fan's definition 7, R's default): x[(n-1)p] interpolated.
double sorted_quantile(const std::vector<double>& sorted, double p);

// Distribution-free interval for the p-quantile from sorted values: [x_(l), x_(u)] with the ranks
// chosen from the binomial distribution of the count below the quantile so that the coverage is
// at least `confidence` (Hahn and Meeker, Statistical Intervals, §5.2). nullopt when n is too
// small for that coverage at this p (a 1 % quantile needs n >= 300 or so for 95 %).
std::optional<Interval> quantile_interval(const std::vector<double>& sorted, double p, double confidence);

// mean -+ t_{n-1} s / sqrt(n), Student's t at two-sided `confidence`; nullopt for n < 2.
std::optional<Interval> mean_interval(const std::vector<double>& x, double confidence);

// Percentile bootstrap (Efron): the statistic over `resamples` resamples of the n rows drawn with
// replacement (random numbers from `seed`), and its (1 - c)/2 and (1 + c)/2 quantiles. Resamples
// whose statistic is NaN are left out; nullopt when more than half are. The statistic gets each
// resample as row indices.
std::optional<Interval> bootstrap_interval(std::size_t n, std::size_t resamples, std::uint64_t seed, double confidence,
                                           const std::function<double(const std::vector<std::size_t>&)>& statistic);

// A seed for one purpose drawn from the run's seed (splitmix64 of both), so that each column's
// and each index's random numbers do not depend on which others were computed.
std::uint64_t derived_seed(std::uint64_t seed, std::uint64_t purpose);

}  // namespace vi
