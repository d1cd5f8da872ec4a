// Where CVODE stops for a prescribed force's time function (TimeFunction::stops): a step, a
// table's first and last knots and its corners, not every row of a sampled signal. A table of many
// rows along a ramp then costs the integrator what the ramp costs, and gives the ramp's response.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>

#include "dynamics/cvode/cvode_solver.hpp"
#include "model/time_function.hpp"
#include "validation/loaded_oscillator.hpp"

namespace vi {
namespace {

// n rows of f on [0, t1].
template <class F>
TimeFunction sampled(std::size_t n, double t1, F f) {
    TimeFunction g;
    g.kind = TimeFunction::Kind::table;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = t1 * static_cast<double>(i) / static_cast<double>(n - 1);
        g.times.push_back(t);
        g.values.push_back(f(t));
    }
    return g;
}

TEST(TimeStops, AStepIsOneStop) {
    TimeFunction g;
    g.kind = TimeFunction::Kind::step;
    g.t_on = 2e-6;
    const std::vector<double> s = g.stops(0.0, 1e-5);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0], 2e-6);
    EXPECT_TRUE(g.stops(0.0, 1e-6).empty());  // outside (t0, t1)
}

// A million rows of one value: nothing to stop at inside the table's span.
TEST(TimeStops, AConstantTableOfAMillionRowsHasNoCorner) {
    const TimeFunction g = sampled(1000000, 50e-6, [](double) { return 70.0; });
    EXPECT_TRUE(g.stops(0.0, 50e-6).empty());
    const std::vector<double> s = g.stops(0.0, 60e-6);  // the last knot, where it is held, is inside
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0], 50e-6);
}

// A ramp to 1 over 1 us, then held, sampled every 5 ns: the stops are its corner, not its rows.
TEST(TimeStops, ASampledRampStopsAtItsCornerOnly) {
    const std::size_t rows = 10001;  // 1 us is 200 of its 5 ns intervals
    const TimeFunction g = sampled(rows, 50e-6, [](double t) { return std::min(t / 1e-6, 1.0); });
    const std::vector<double> s = g.stops(0.0, 50e-6);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_NEAR(s[0], 1e-6, 1e-15);
}

// One row 1e-3 above a flat table: its three knots are corners (a short feature is never stepped over).
TEST(TimeStops, ANarrowSpikeKeepsItsCorners) {
    TimeFunction g = sampled(100001, 1e-5, [](double) { return 1.0; });
    g.values[50000] = 1.001;
    const std::vector<double> s = g.stops(0.0, 1e-5);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0], g.times[49999]);
    EXPECT_EQ(s[1], g.times[50000]);
    EXPECT_EQ(s[2], g.times[50001]);
}

// Between two stops every row lies within kTableStopTolerance of the table's peak of the straight
// line between them, and the stops follow that tolerance, not the rows: a sine sampled over 3
// periods keeps as many with 2e5 rows as with 1e5, below the chord bound 3 x 2 pi / sqrt(8 tol)
// (a chord of a unit sine over a phase p departs from it by p^2 / 8).
TEST(TimeStops, EveryRowBetweenStopsIsWithinTheToleranceOfTheirChord) {
    const double f = 3.0 / 1e-5;
    const auto sine = [&](double t) { return 2.0 + std::sin(2.0 * std::numbers::pi * f * t); };
    const TimeFunction g = sampled(100000, 1e-5, sine);
    const std::vector<double> s = g.stops(-1.0, 1.0);
    const std::size_t twice = sampled(200000, 1e-5, sine).stops(-1.0, 1.0).size();
    std::printf("sampled sine: %zu stops for 1e5 rows, %zu for 2e5 rows\n", s.size(), twice);
    ASSERT_GE(s.size(), 2u);
    EXPECT_EQ(s.front(), g.times.front());
    EXPECT_EQ(s.back(), g.times.back());
    const double tol = kTableStopTolerance * 3.0;  // the peak |g| is 3
    EXPECT_LT(static_cast<double>(s.size()), 3.0 * 2.0 * std::numbers::pi / std::sqrt(8.0 * tol));
    EXPECT_NEAR(static_cast<double>(twice), static_cast<double>(s.size()), 0.05 * static_cast<double>(s.size()));
    std::size_t k = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < g.times.size(); ++i) {
        while (k + 1 < s.size() && s[k + 1] <= g.times[i]) ++k;
        if (k + 1 >= s.size()) break;
        const double a = s[k], b = s[k + 1];
        const double chord = g(a) + (g(b) - g(a)) * (g.times[i] - a) / (b - a);
        worst = std::max(worst, std::abs(g.values[i] - chord));
    }
    EXPECT_LE(worst, tol * (1.0 + 1e-9));
    EXPECT_GT(worst, 0.3 * tol);  // the stops are not denser than the tolerance asks
}

// Noise has a corner at every row: each is a stop.
TEST(TimeStops, NoiseStopsAtEveryRow) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    const TimeFunction g = sampled(1000, 1e-5, [&](double) { return 70.0 + u(rng); });
    EXPECT_EQ(g.stops(-1.0, 1.0).size(), 1000u);
}

// The oscillator under a ramp to F over 1.3 periods, then held, given as 2 rows and as 20001 rows
// of the same ramp: CVODE's response to both is the closed form's to 1e-6, and the many rows cost
// no more steps than the two (a stop and restart at every row cost 7 steps each).
TEST(TimeStops, ARampOfManyRowsCostsWhatTheRampCosts) {
    LoadedOscillator o;
    const double t_ramp = 1.3 * o.period(), t_end = 4.0 * o.period();
    o.g.kind = TimeFunction::Kind::table;
    o.g.times = {0.0, t_ramp};
    o.g.values = {0.0, 1.0};
    const TransientResult two = solve_cvode(o.problem(t_end, o.period() / 40.0));
    LoadedOscillator dense = o;
    dense.g = sampled(20001, t_end, [&](double t) { return std::min(t / t_ramp, 1.0); });
    dense.g.times[6500] = t_ramp;  // a row on the corner
    dense.g.values[6500] = 1.0;
    const TransientResult many = solve_cvode(dense.problem(t_end, o.period() / 40.0));
    const double scale = o.force / o.stiffness;
    EXPECT_LT(load_response_error(o, two, scale).response, 1e-6);
    EXPECT_LT(load_response_error(o, many, scale).response, 1e-6);
    std::printf("steps: 2 rows %d, 20001 rows %d\n", two.stats.steps, many.stats.steps);
    EXPECT_LT(many.stats.steps, 2 * two.stats.steps);
}

}  // namespace
}  // namespace vi
