// The spread estimators on problems with known answers: distributions' moments, the designs'
// stratification, the coverage of the mean, quantile, standard-deviation and yield intervals over
// many independent samples, and Sobol indices of the Ishigami function and of a linear model against
// their closed forms, through the same code the uq command runs (uq/).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "model/input_error.hpp"
#include "uq/distribution.hpp"
#include "uq/sampling.hpp"
#include "uq/sobol_indices.hpp"
#include "uq/statistics.hpp"
#include "uq/yield.hpp"

namespace vi {
namespace {

constexpr double kPi = std::numbers::pi;

// n draws of d by inverse CDF from independent uniforms of seed.
std::vector<double> draws(const Distribution& d, std::size_t n, std::uint64_t seed) {
    const std::vector<double> u = unit_cube_points(SamplingMethod::mc, n, 1, seed);
    std::vector<double> x;
    for (double v : u) x.push_back(d.quantile(v));
    return x;
}

// The fraction of `reps` independent samples whose interval holds `truth`, and the binomial band
// 0.95 -+ 4 sigma that an interval of 95 % coverage keeps to (4 sigma: one failure in 15 000).
struct Coverage {
    std::size_t held = 0, total = 0;
    void add(const std::optional<Interval>& i, double truth) {
        ++total;
        held += i && i->low <= truth && truth <= i->high ? 1 : 0;
    }
    [[nodiscard]] double rate() const { return static_cast<double>(held) / static_cast<double>(total); }
    [[nodiscard]] double band() const { return 4.0 * std::sqrt(0.95 * 0.05 / static_cast<double>(total)); }
};

TEST(UqDistributions, MomentsAndQuantilesOfEachKind) {
    const Distribution n = parse_distribution("normal:2:0.1");
    EXPECT_DOUBLE_EQ(n.mean(), 2.0);
    EXPECT_NEAR(n.quantile(0.975), 2.0 + 1.959963984540054 * 0.1, 1e-12);
    const Distribution u = parse_distribution("uniform:1:3");
    EXPECT_DOUBLE_EQ(u.quantile(0.25), 1.5);
    EXPECT_NEAR(u.std_dev(), 2.0 / std::sqrt(12.0), 1e-15);
    const Distribution l = parse_distribution("lognormal:2:0.5");
    EXPECT_NEAR(l.quantile(0.5), 2.0, 1e-15);
    EXPECT_NEAR(l.mean(), 2.0 * std::exp(0.125), 1e-14);
    EXPECT_NEAR(l.std_dev(), l.mean() * std::sqrt(std::expm1(0.25)), 1e-14);
    // A symmetric truncation keeps the mean; a half-normal (truncated at the mean) has the mean
    // mu + sigma sqrt(2 / pi) and the variance sigma^2 (1 - 2 / pi); here the upper bound is 40 SD out.
    const Distribution t = parse_distribution("truncnormal:0:1:-1.5:1.5");
    EXPECT_NEAR(t.mean(), 0.0, 1e-15);
    EXPECT_GT(t.quantile(1e-9), -1.5);
    EXPECT_LT(t.quantile(1 - 1e-9), 1.5);
    const Distribution h = parse_distribution("truncnormal:1:1:0.999999999:40");
    EXPECT_NEAR(h.mean(), 1.0 + std::sqrt(2.0 / kPi), 1e-8);
    EXPECT_NEAR(h.std_dev(), std::sqrt(1.0 - 2.0 / kPi), 1e-8);
    // Units as case files write them.
    EXPECT_NEAR(parse_distribution("normal:2um:50nm", Dimension::length).b, 5e-8, 1e-22);
    // Sample moments of 200 000 draws agree with the closed forms to a few of their standard errors.
    for (const char* text : {"normal:2:0.1", "uniform:1:3", "lognormal:2:0.5", "truncnormal:0:1:-0.5:2"}) {
        const Distribution d = parse_distribution(text);
        const std::vector<double> x = draws(d, 200000, 7);
        EXPECT_NEAR(sample_mean(x), d.mean(), 5.0 * d.std_dev() / std::sqrt(200000.0)) << text;
        EXPECT_NEAR(sample_std(x) / d.std_dev(), 1.0, 0.01) << text;
    }
}

TEST(UqDistributions, RefusalsSayWhy) {
    const auto message = [](const std::string& text) {
        try {
            (void)parse_distribution(text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("gauss:1:2"), "unknown distribution 'gauss' (normal:MEAN:SD, uniform:LOW:HIGH, "
                                    "lognormal:MEDIAN:SIGMA_LOG, truncnormal:MEAN:SD:LOW:HIGH)");
    EXPECT_EQ(message("normal:1:0"), "normal: SD must be positive (got 0)");
    EXPECT_EQ(message("normal:1:-2"), "normal: SD must be positive (got -2)");
    EXPECT_EQ(message("normal:1"), "normal takes 2 values: normal:MEAN:SD");
    EXPECT_EQ(message("uniform:3:1"), "uniform: LOW must be below HIGH");
    EXPECT_EQ(message("lognormal:0:0.1"), "lognormal: MEDIAN must be positive");
    EXPECT_EQ(message("lognormal:1:0"), "lognormal: SIGMA_LOG must be positive");
    EXPECT_EQ(message("truncnormal:1:0.1:1.2:2"), "truncnormal: the bounds 1.2 .. 2 must hold the mean 1 between them");
    EXPECT_EQ(message("truncnormal:1:0.1:2:0"), "truncnormal: LOW must be below HIGH");
    EXPECT_NE(message("normal:x:1").find("x"), std::string::npos);
}

TEST(UqSampling, DesignsStratifyAndDependOnTheSeedAlone) {
    const std::size_t n = 256, d = 5;
    for (SamplingMethod m : {SamplingMethod::mc, SamplingMethod::lhs, SamplingMethod::sobol}) {
        const std::vector<double> x = unit_cube_points(m, n, d, 3);
        EXPECT_EQ(x, unit_cube_points(m, n, d, 3)) << sampling_method_name(m);
        EXPECT_NE(x, unit_cube_points(m, n, d, 4)) << sampling_method_name(m);
        for (double v : x) ASSERT_TRUE(v > 0.0 && v < 1.0);
        if (m == SamplingMethod::mc) continue;
        // LHS puts one point in each of n equal strata of every coordinate; the first 2^8 points of
        // the Sobol sequence, digitally shifted, do the same in every one-dimensional projection.
        for (std::size_t j = 0; j < d; ++j) {
            std::set<std::size_t> strata;
            for (std::size_t i = 0; i < n; ++i) strata.insert(static_cast<std::size_t>(x[i * d + j] * n));
            EXPECT_EQ(strata.size(), n) << sampling_method_name(m) << " coordinate " << j;
        }
    }
}

// Over 2000 independent samples of 100 normal values, the t interval of the mean and the order-
// statistic intervals of the 5 % and 50 % quantiles hold the truth at least 95 % of the time (the
// order-statistic ones by construction, so up to their discrete excess).
TEST(UqIntervals, MeanAndQuantileIntervalsCoverTheTruth) {
    const Distribution d = parse_distribution("normal:10:2");
    Coverage mean, q5, q50;
    for (std::uint64_t rep = 0; rep < 2000; ++rep) {
        std::vector<double> x = draws(d, 100, 1000 + rep);
        mean.add(mean_interval(x, 0.95), 10.0);
        std::sort(x.begin(), x.end());
        q5.add(quantile_interval(x, 0.05, 0.95), d.quantile(0.05));
        q50.add(quantile_interval(x, 0.5, 0.95), 10.0);
    }
    std::printf("coverage over %zu samples: mean %.4f, q5 %.4f, q50 %.4f\n", mean.total, mean.rate(), q5.rate(), q50.rate());
    EXPECT_NEAR(mean.rate(), 0.95, mean.band());
    EXPECT_GE(q5.rate(), 0.95 - q5.band());
    EXPECT_GE(q50.rate(), 0.95 - q50.band());
    // Too few values for a 1 % quantile's interval at 95 %: none is given rather than a short one.
    std::vector<double> few = draws(d, 100, 1);
    std::sort(few.begin(), few.end());
    EXPECT_FALSE(quantile_interval(few, 0.01, 0.95).has_value());
    EXPECT_TRUE(quantile_interval(few, 0.05, 0.95).has_value());
    // The least n for each: (1 - p)^n <= 0.025, so 368 for 1 % and 99 %, 72 for 5 %, 6 for the median.
    for (const auto& [p, least] : {std::pair{0.01, 368}, std::pair{0.99, 368}, std::pair{0.05, 72}, std::pair{0.5, 6}}) {
        std::vector<double> x(static_cast<std::size_t>(least - 1));
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i);
        EXPECT_FALSE(quantile_interval(x, p, 0.95).has_value()) << p;
        x.push_back(static_cast<double>(x.size()));
        EXPECT_TRUE(quantile_interval(x, p, 0.95).has_value()) << p;
    }
}

// The percentile bootstrap of the standard deviation is close to its nominal coverage for a normal
// sample of 200 (it runs a little short for small samples: Efron and Tibshirani 1993, §13.3).
TEST(UqIntervals, BootstrapOfTheStandardDeviationCoversTheTruth) {
    const Distribution d = parse_distribution("normal:0:1");
    Coverage sd;
    for (std::uint64_t rep = 0; rep < 400; ++rep) {
        const std::vector<double> x = draws(d, 200, 5000 + rep);
        sd.add(bootstrap_interval(x.size(), 500, derived_seed(rep, 1), 0.95,
                                  [&](const std::vector<std::size_t>& rows) {
                                      std::vector<double> y;
                                      for (std::size_t r : rows) y.push_back(x[r]);
                                      return sample_std(y);
                                  }),
               1.0);
    }
    std::printf("bootstrap coverage of the SD over %zu samples: %.4f\n", sd.total, sd.rate());
    EXPECT_NEAR(sd.rate(), 0.95, sd.band());
}

TEST(UqIntervals, WilsonIntervalAndItsCoverage) {
    // Brown, Cai and DasGupta (2001), and the closed form at 0 successes: [0, z^2 / (n + z^2)].
    const Interval none = wilson_interval(0, 10, 0.95);
    EXPECT_EQ(none.low, 0.0);
    EXPECT_NEAR(none.high, 3.841458820694124 / (10.0 + 3.841458820694124), 1e-12);
    const Interval all = wilson_interval(10, 10, 0.95);
    EXPECT_NEAR(all.low, 1.0 - none.high, 1e-12);
    EXPECT_NEAR(all.high, 1.0, 1e-15);
    // Coverage for p = 0.9 with n = 200 over 2000 independent counts.
    Coverage y;
    for (std::uint64_t rep = 0; rep < 2000; ++rep) {
        const std::vector<double> u = unit_cube_points(SamplingMethod::mc, 200, 1, 90000 + rep);
        const std::size_t passed = static_cast<std::size_t>(std::count_if(u.begin(), u.end(), [](double v) { return v < 0.9; }));
        const Interval i = wilson_interval(passed, 200, 0.95);
        y.add(i, 0.9);
    }
    std::printf("Wilson coverage at p = 0.9, n = 200: %.4f\n", y.rate());
    EXPECT_NEAR(y.rate(), 0.95, y.band());
    // +-2 % at a 90 % yield takes 1.96^2 0.09 / 0.02^2 = 865 samples.
    EXPECT_EQ(samples_for_yield(0.9, 0.02, 0.95), 865u);
}

TEST(UqIntervals, SpecsNameANumericColumn) {
    const std::vector<std::string> cols = {"pullin_voltage_v", "hysteresis_v"};
    const YieldSpec s = parse_yield_spec("pullin_voltage_v<=40", cols);
    EXPECT_TRUE(s.upper);
    EXPECT_EQ(s.bound, 40.0);
    EXPECT_TRUE(s.met(40.0));
    EXPECT_FALSE(s.met(std::nan("")));
    EXPECT_FALSE(parse_yield_spec("hysteresis_v>=2", cols).upper);
    try {
        (void)parse_yield_spec("pull_in<=40", cols);
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "--spec pull_in<=40: no numeric column 'pull_in' in this analysis (one of: "
                                         "pullin_voltage_v, hysteresis_v)");
    }
    EXPECT_THROW((void)parse_yield_spec("pullin_voltage_v<40", cols), InputError);
    EXPECT_THROW((void)parse_yield_spec("pullin_voltage_v<=forty", cols), InputError);
}

// Saltelli's runs of a function of d inputs uniform on (-pi, pi): f(A), f(B), f(A_B^i).
template <class F>
SobolEstimate saltelli_of(F f, std::size_t d, std::size_t n, SamplingMethod m, std::uint64_t seed, std::size_t resamples) {
    const std::vector<double> u = unit_cube_points(m, n, 2 * d, seed);
    const auto x = [&](std::size_t j, std::size_t i, bool from_b) { return -kPi + 2.0 * kPi * u[j * 2 * d + (from_b ? d : 0) + i]; };
    std::vector<double> fa(n), fb(n);
    std::vector<std::vector<double>> fab(d, std::vector<double>(n));
    std::vector<double> p(d);
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t i = 0; i < d; ++i) p[i] = x(j, i, false);
        fa[j] = f(p);
        for (std::size_t i = 0; i < d; ++i) p[i] = x(j, i, true);
        fb[j] = f(p);
        for (std::size_t k = 0; k < d; ++k) {
            for (std::size_t i = 0; i < d; ++i) p[i] = x(j, i, i == k);
            fab[k][j] = f(p);
        }
    }
    return sobol_indices(fa, fb, fab, resamples, seed, 0.95);
}

// Ishigami and Homma (1990): f = sin x1 + a sin^2 x2 + b x3^4 sin x1, x_i uniform on (-pi, pi),
// a = 7, b = 0.1. V = a^2/8 + b pi^4/5 + b^2 pi^8/18 + 1/2, V1 = (1 + b pi^4/5)^2 / 2, V2 = a^2/8,
// V3 = 0, V13 = 8 b^2 pi^8 / 225 (Saltelli et al., Global Sensitivity Analysis: The Primer, 2008).
TEST(UqSobol, IshigamiIndicesAgainstTheirClosedForms) {
    const double a = 7.0, b = 0.1;
    const auto ishigami = [&](const std::vector<double>& x) {
        return std::sin(x[0]) + a * std::pow(std::sin(x[1]), 2) + b * std::pow(x[2], 4) * std::sin(x[0]);
    };
    const double pi4 = std::pow(kPi, 4), pi8 = std::pow(kPi, 8);
    const double v = a * a / 8 + b * pi4 / 5 + b * b * pi8 / 18 + 0.5;
    const double v1 = 0.5 * std::pow(1 + b * pi4 / 5, 2), v2 = a * a / 8, v13 = 8 * b * b * pi8 / 225;
    const double first[3] = {v1 / v, v2 / v, 0.0};
    const double total[3] = {(v1 + v13) / v, v2 / v, v13 / v};
    // A large Sobol design: the estimates themselves within 0.01 of the closed forms.
    const SobolEstimate big = saltelli_of(ishigami, 3, 1 << 14, SamplingMethod::sobol, 1, 200);
    ASSERT_EQ(big.inputs.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        std::printf("S%zu %.4f (exact %.4f), ST%zu %.4f (exact %.4f)\n", i + 1, big.inputs[i].first, first[i], i + 1,
                    big.inputs[i].total, total[i]);
        EXPECT_NEAR(big.inputs[i].first, first[i], 0.01);
        EXPECT_NEAR(big.inputs[i].total, total[i], 0.01);
    }
    EXPECT_NEAR(big.variance, v, 0.01 * v);
    // Independent Monte Carlo designs of N = 512: their 95 % bootstrap intervals hold the closed forms
    // about 95 % of the time (the percentile bootstrap runs slightly short: the band is 4 sigma).
    Coverage c;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        const SobolEstimate e = saltelli_of(ishigami, 3, 512, SamplingMethod::mc, 100 + seed, 300);
        for (std::size_t i = 0; i < 3; ++i) {
            c.add(e.inputs[i].has_ci ? std::optional<Interval>(e.inputs[i].first_ci) : std::nullopt, first[i]);
            c.add(e.inputs[i].has_ci ? std::optional<Interval>(e.inputs[i].total_ci) : std::nullopt, total[i]);
        }
    }
    std::printf("Ishigami: %zu of %zu intervals hold the closed form (%.3f)\n", c.held, c.total, c.rate());
    EXPECT_NEAR(c.rate(), 0.95, c.band());
}

// Y = sum a_i X_i with independent inputs: S_i = S_Ti = a_i^2 V_i / sum a_k^2 V_k; a row with a
// missing value is left out of every index.
TEST(UqSobol, LinearModelAndMissingRows) {
    const double a[3] = {1.0, 2.0, 0.0};
    const auto linear = [&](const std::vector<double>& x) { return a[0] * x[0] + a[1] * x[1] + a[2] * x[2]; };
    const SobolEstimate e = saltelli_of(linear, 3, 1 << 13, SamplingMethod::sobol, 9, 200);
    EXPECT_NEAR(e.inputs[0].first, 0.2, 0.01);
    EXPECT_NEAR(e.inputs[1].first, 0.8, 0.01);
    EXPECT_NEAR(e.inputs[2].first, 0.0, 1e-12);
    EXPECT_NEAR(e.inputs[2].total, 0.0, 1e-12);
    EXPECT_NEAR(e.inputs[1].total, 0.8, 0.01);
    std::vector<double> fa = {1, 2, std::nan(""), 4}, fb = {2, 1, 3, 3};
    std::vector<std::vector<double>> fab = {{1, 2, 3, 4}};
    EXPECT_EQ(sobol_indices(fa, fb, fab, 100, 1, 0.95).rows, 3u);
    // A constant output has no indices.
    EXPECT_TRUE(sobol_indices({1, 1, 1}, {1, 1, 1}, {{1, 1, 1}}, 100, 1, 0.95).inputs.empty());
}

}  // namespace
}  // namespace vi
