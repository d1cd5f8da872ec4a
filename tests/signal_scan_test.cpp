// The certified bounds of the exact solver against dense sampling of random exponential signals:
// upper bounds are upper bounds, certified steps contain no zero, maxima and crossings are found.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "dynamics/signal/event_search.hpp"
#include "dynamics/signal/signal_scan.hpp"

namespace vi {
namespace {

// A signal shaped like a beam response: lightly damped pairs (one representative each, as the
// solver keeps them), heavily damped real modes that die within a fraction of the span, and a
// constant; exponents in ascending magnitude. Amplitudes spread over several decades.
struct RandomSignal {
    Eigen::VectorXcd lambda;
    ExpSignal f;
};

RandomSignal random_signal(std::mt19937& rng, double offset) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    RandomSignal r;
    std::vector<cd> lam, amp;
    for (int k = 0; k < 12; ++k) {
        const double w = 1e6 * std::pow(10.0, 3.0 * u(rng));  // 1e6 .. 1e9 rad/s
        lam.emplace_back(-w * 0.02 * u(rng), w);
        amp.push_back(std::polar(std::pow(10.0, -3.0 * u(rng)), 6.3 * u(rng)));
    }
    for (int k = 0; k < 10; ++k) {
        lam.emplace_back(-std::pow(10.0, 7.0 + 5.0 * u(rng)), 0.0);  // overdamped: 1e7 .. 1e12 1/s
        amp.emplace_back(std::pow(10.0, -2.0 * u(rng)) * (u(rng) < 0.5 ? -1.0 : 1.0), 0.0);
    }
    std::vector<int> order(lam.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(lam[static_cast<std::size_t>(a)]) < std::abs(lam[static_cast<std::size_t>(b)]); });
    r.lambda.resize(static_cast<Eigen::Index>(lam.size()));
    r.f.A.resize(static_cast<Eigen::Index>(lam.size()));
    for (std::size_t k = 0; k < order.size(); ++k) {
        r.lambda[static_cast<Eigen::Index>(k)] = lam[static_cast<std::size_t>(order[k])];
        r.f.A[static_cast<Eigen::Index>(k)] = amp[static_cast<std::size_t>(order[k])];
    }
    if (offset != 0.0) r.f.terms.push_back({offset, 0.0, 0});
    return r;
}

// f sampled finely: the largest value over [a, b].
double sampled_max(const ExpSignal& f, double a, double b, int samples) {
    double best = -1e300;
    for (int i = 0; i <= samples; ++i) best = std::max(best, f.value(a + (b - a) * i / samples));
    return best;
}

TEST(SignalScan, PointValueIsTheSignalAndBoundsHoldOnRandomIntervals) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        RandomSignal r = random_signal(rng, 0.5 * (u(rng) - 0.5));
        r.f.lambda = &r.lambda;
        SignalScan scan(r.f, 1.0, 1e-5);
        for (int i = 0; i < 20; ++i) {
            const double a = 1e-5 * std::pow(u(rng), 3.0);
            const double h = std::min(1e-5 - a, 1e-5 * std::pow(10.0, -4.0 * u(rng)));
            const ScanPoint pa = scan.evaluate(a);
            const ScanPoint pb = scan.evaluate(a + h);
            const double size = pa.abs0;
            EXPECT_NEAR(pa.value, r.f.value(a), 1e-14 * size);
            EXPECT_NEAR(pa.slope, r.f.derivative(a, 1), 1e-13 * pa.abs1);
            const double bound = scan.upper_bound(pa, pb);
            EXPECT_GE(bound, sampled_max(r.f, a, a + h, 400) - 1e-14 * size) << "trial " << trial << " a " << a << " h " << h;
        }
    }
}

TEST(SignalScan, CertifiedStepsContainNoZero) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int steps = 0;
    for (int trial = 0; trial < 40; ++trial) {
        RandomSignal r = random_signal(rng, 0.0);
        r.f.lambda = &r.lambda;
        // Shift the signal below zero by a random margin so that it comes close to 0 somewhere.
        const double top = sampled_max(r.f, 0.0, 1e-5, 20000);
        r.f.terms.push_back({-(top + std::pow(10.0, -6.0 * u(rng))), 0.0, 0});
        SignalScan scan(r.f, 1.0, 1e-5);
        double t = 0.0;
        for (int i = 0; i < 200 && t < 1e-5; ++i) {
            const ScanPoint p = scan.evaluate(t);
            // The signal may touch zero where the sampled top missed its peak: the trial ends at
            // roundoff distance from it (the steps shrink like sqrt(|f|)).
            const double noise = 64.0 * std::numeric_limits<double>::epsilon() * p.abs0;
            if (!(p.value < -noise)) break;
            const double h = scan.certified_step(p, 1e-5 - t, p.value);
            if (h <= 0.0) break;
            EXPECT_LT(sampled_max(r.f, t, t + h, 200), noise) << "trial " << trial << " t " << t << " h " << h;
            t += h;
            ++steps;
        }
    }
    EXPECT_GT(steps, 200);
}

TEST(SignalScan, MaximaAgreeWithDenseSampling) {
    std::mt19937 rng(3);
    for (int trial = 0; trial < 30; ++trial) {
        RandomSignal r = random_signal(rng, 0.1);
        r.f.lambda = &r.lambda;
        const double span = 1e-5;
        const double sampled = sampled_max(r.f, 0.0, span, 20000);
        for (const double sign : {1.0, -1.0}) {
            ExpSignal g = r.f;
            if (sign < 0.0) {
                g.A = -g.A;
                for (ExpTerm& t : g.terms) t.coef = -t.coef;
            }
            const double want = sign > 0.0 ? sampled : sampled_max(g, 0.0, span, 20000);
            const SignalMaximum m = global_maximum(r.f, span, 0.0, 1e-9, 1e-18, nullptr,
                                                   -std::numeric_limits<double>::infinity(), sign);
            // The maximum found is a value the signal takes, and no sample beats it by more than
            // the tolerance.
            EXPECT_NEAR(m.value, sign * r.f.value(m.tau), 1e-14 * std::abs(m.value));
            EXPECT_GE(m.value, want - 1e-9 * std::abs(want)) << "trial " << trial << " sign " << sign;
        }
    }
}

TEST(SignalScan, FirstUpcrossingIsTheFirstSampledCrossing) {
    std::mt19937 rng(5);
    for (int trial = 0; trial < 30; ++trial) {
        RandomSignal r = random_signal(rng, 0.0);
        r.f.lambda = &r.lambda;
        const double span = 1e-5;
        // Put the level so that the signal crosses it, but only briefly, somewhere in the span.
        const double top = sampled_max(r.f, 0.0, span, 20000);
        const double level = top * (1.0 - 1e-3);
        r.f.terms.push_back({-level, 0.0, 0});
        if (r.f.value(0.0) >= 0.0) continue;
        CrossingSearch cs;
        cs.h_min = 1e-18;
        cs.t_tol = 1e-20;
        const auto hit = first_upcrossing(r.f, 0.0, span, cs);
        ASSERT_TRUE(hit.has_value()) << trial;
        // Positive, or within roundoff of zero (the scan leaves out modes below 1e-18 of the size).
        const double size = r.f.bound(0.0, 0.0, 0);
        EXPECT_GT(r.f.value(*hit), -1e-15 * size);
        // No sample before it is positive.
        EXPECT_LE(sampled_max(r.f, 0.0, *hit - cs.t_tol, 50000), 0.0) << trial;
    }
}

// f = cos t - (1 - delta) rises above zero only within sqrt(2 delta) of t = 2 pi. With the smallest
// step ten times that wide the search may step over it; it must then say so: the forced steps are
// counted and the largest bound over them covers the peak delta it did not see.
TEST(SignalScan, ACrossingNarrowerThanTheSmallestStepIsReportedWhenStepped) {
    Eigen::VectorXcd lambda(1);
    lambda[0] = cd(0.0, 1.0);
    const double delta = 1e-6, t_star = 2.0 * std::numbers::pi - std::acos(1.0 - delta);
    CrossingSearch cs;
    cs.h_min = 20.0 * std::sqrt(2.0 * delta);
    cs.t_tol = 1e-14;
    int found = 0, stepped = 0;
    for (int trial = 0; trial < 40; ++trial) {
        ExpSignal f;
        f.lambda = &lambda;
        f.A = Eigen::VectorXcd::Ones(1);
        f.terms.push_back({-(1.0 - delta), 0.0, 0});
        const double tau0 = 0.3 + 0.02 * trial;  // a different alignment of the steps each time
        UnprovenSteps unproven;
        const auto hit = first_upcrossing(f, tau0, 7.0, cs, nullptr, &unproven);
        if (hit && std::abs(*hit - t_star) < 1e-9) {
            ++found;
            continue;
        }
        ++stepped;
        EXPECT_TRUE(!hit || *hit > t_star) << trial;
        ASSERT_GT(unproven.count, 0) << trial;
        const double size = 2.0 - delta;  // |A| + |constant|
        EXPECT_GE(unproven.excess * size, delta) << trial;
        // and not uselessly loose: the bound of a step of length h over a unit-curvature signal
        EXPECT_LE(unproven.excess * size, cs.h_min * cs.h_min) << trial;
    }
    // Both outcomes occur over these alignments, so both branches above were exercised.
    EXPECT_GT(found, 0);
    EXPECT_GT(stepped, 0);
}

// The integral from exponentials given by the caller (the solver passes its piece-end ones) is the
// plain one to the last bit when they are fast_exp's, and a constant term's exponential is 1 exactly.
TEST(SignalScan, IntegralFromGivenExponentialsIsTheSameToTheLastBit) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        RandomSignal r = random_signal(rng, u(rng) - 0.5);
        r.f.lambda = &r.lambda;
        const double tau = 1e-5 * std::pow(u(rng), 2.0);
        Eigen::VectorXcd e(r.lambda.size());
        for (Eigen::Index k = 0; k < e.size(); ++k) e[k] = fast_exp(r.lambda[k], tau);
        EXPECT_EQ(r.f.integral(tau, e), r.f.integral(tau)) << trial;
        EXPECT_EQ(fast_exp(cd(0.0, 0.0), tau), cd(std::exp(0.0 * tau), 0.0));
    }
}

}  // namespace
}  // namespace vi
