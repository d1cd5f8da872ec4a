// The one golden-section search against maxima known in closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/golden_section.hpp"

namespace vi {
namespace {

TEST(GoldenSection, FindsTheMaximumToTheWidthAsked) {
    int calls = 0;
    const auto parabola = [&](double x) {
        ++calls;
        return 2.0 - (x - 0.3) * (x - 0.3);
    };
    const GoldenSectionPeak p = golden_section_max(parabola, 0.0, 1.0, 1e-9);
    // At a smooth peak f is flat to roundoff within sqrt(eps) (1.5e-8) of it: there the comparisons
    // cannot tell, and x is known to that, whatever the width asked; the value to roundoff.
    EXPECT_NEAR(p.x, 0.3, 3e-8);
    EXPECT_NEAR(p.value, 2.0, 1e-15);
    EXPECT_DOUBLE_EQ(p.value, 2.0 - (p.x - 0.3) * (p.x - 0.3));
    // One evaluation per pass: log(1e-9) / log(0.618) = 43 passes, two to start, one at the end.
    EXPECT_LE(calls, 47);
    EXPECT_GE(calls, 45);

    // Not symmetric about the peak, which lies near one end of the interval.
    const GoldenSectionPeak s = golden_section_max([](double x) { return std::sin(x); }, 0.0, 1.6, 1e-10);
    EXPECT_NEAR(s.x, std::numbers::pi / 2.0, 3e-8);

    // A kink is not flat: there the bracket closes on it to the width asked.
    const GoldenSectionPeak k = golden_section_max([](double x) { return -std::abs(x - 0.3); }, 0.0, 1.0, 1e-9);
    EXPECT_NEAR(k.x, 0.3, 1e-9);
}

TEST(GoldenSection, AWidthBelowRoundoffEndsAtRoundoff) {
    const GoldenSectionPeak p = golden_section_max([](double x) { return -std::abs(x - 1.0); }, 0.5, 2.0, 0.0);
    EXPECT_NEAR(p.x, 1.0, 4e-16);
}

}  // namespace
}  // namespace vi
