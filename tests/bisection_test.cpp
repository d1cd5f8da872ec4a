// The one bisection against roots known in closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/bisection.hpp"

namespace vi {
namespace {

TEST(Bisection, FindsASignChangeToMachinePrecision) {
    const double r = bisect_sign_change([](double x) { return std::cos(x); }, 1.0, 2.0);
    EXPECT_NEAR(r, std::numbers::pi / 2.0, 4e-16);
    // Either sign at the lower end.
    const double s = bisect_sign_change([](double x) { return 2.0 - x * x; }, 1.0, 2.0);
    EXPECT_NEAR(s, std::sqrt(2.0), 4e-16);
}

TEST(Bisection, AnExactZeroEndsTheSearchThere) {
    int calls = 0;
    const double r = bisect_sign_change(
        [&](double x) {
            ++calls;
            return x - 0.5;
        },
        0.0, 1.0);
    EXPECT_EQ(r, 0.5);
    EXPECT_EQ(calls, 2);  // f(a), then f at the midpoint 0.5
}

}  // namespace
}  // namespace vi
