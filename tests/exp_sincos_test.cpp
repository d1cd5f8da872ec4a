// The signal scans' array exponentials against long-double references: within the 4 ulps the scans'
// rounding bounds allow per term, over the arguments the exact solver meets and at the edges of the
// range the arithmetic pass covers.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "dynamics/signal/exp_sincos.hpp"

namespace vi {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Worst {
    double exp_ulps = 0.0;  // relative to exp(x)
    double trig_eps = 0.0;  // relative to 1, the size of (cos, sin)
};

Worst worst_error(const std::vector<double>& x, const std::vector<double>& y) {
    const int n = static_cast<int>(x.size());
    std::vector<double> e(x.size()), c(x.size()), s(x.size());
    exp_sincos(x.data(), y.data(), e.data(), c.data(), s.data(), n);
    Worst w;
    for (int k = 0; k < n; ++k) {
        if (x[k] >= -707.0) {
            const long double ref = std::exp(static_cast<long double>(x[k]));
            w.exp_ulps = std::max(w.exp_ulps, static_cast<double>(std::fabs((e[k] - ref) / ref)) / kEps);
        } else {
            EXPECT_EQ(e[k], 1e-307) << "x = " << x[k];
        }
        const long double yl = y[k];
        const double dc = static_cast<double>(std::fabs(c[k] - std::cos(yl)));
        const double ds = static_cast<double>(std::fabs(s[k] - std::sin(yl)));
        w.trig_eps = std::max({w.trig_eps, dc / kEps, ds / kEps});
    }
    return w;
}

TEST(ExpSincos, WithinFourUlpsOverTheSolversArguments) {
    // Decay exponents from the floor to slight growth; phases from 1e-8 rad to 3e5 rad of either
    // sign (past 1e5 the C library takes over), log-uniform.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> x, y;
    for (int k = 0; k < 200000; ++k) {
        x.push_back(-720.0 + 730.0 * u(rng));
        const double mag = std::pow(10.0, -8.0 + 13.5 * u(rng));
        y.push_back(u(rng) < 0.5 ? -mag : mag);
    }
    const Worst w = worst_error(x, y);
    EXPECT_LT(w.exp_ulps, 4.0);
    EXPECT_LT(w.trig_eps, 4.0);
}

TEST(ExpSincos, EdgesOfTheRange) {
    // Zero (every factor exactly 1 and 0), quadrant boundaries, the exp floor and the hand-over
    // points to the C library on both sides.
    const double pi = std::acos(-1.0);
    const std::vector<double> x = {0.0, -706.9, -707.1, 699.9, 700.1, -1e-300, -0.5 * std::log(2.0), 1e-12};
    const std::vector<double> y = {0.0, 0.5 * pi, pi, 1.5 * pi, -0.5 * pi, 1e5, -1e5 - 1.0, 2e5};
    std::vector<double> e(x.size()), c(x.size()), s(x.size());
    exp_sincos(x.data(), y.data(), e.data(), c.data(), s.data(), static_cast<int>(x.size()));
    EXPECT_EQ(e[0], 1.0);
    EXPECT_EQ(c[0], 1.0);
    EXPECT_EQ(s[0], 0.0);
    const Worst w = worst_error(x, y);
    EXPECT_LT(w.exp_ulps, 4.0);
    EXPECT_LT(w.trig_eps, 4.0);
}

}  // namespace
}  // namespace vi
