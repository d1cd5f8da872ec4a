// The supported beam's first frequency peaks with the support near x0/l = 0.78 (paper Fig. 8).

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/closed_forms.hpp"
#include "analysis/support_scan.hpp"
#include "paper_cases.hpp"

namespace vi {
namespace {

double first_ratio(double x0) {
    const Case c = test::paper_cantilever(50, x0);
    return modal_study(c, 1, SupportModel::pin).ratios.at(0);
}

TEST(SupportScan, FirstFrequencyRatioPeaksNear078At627) {
    // Coarse scan, then golden-section search around the best point.
    double best = 0.02;
    for (double x = 0.02; x <= 1.0 + 1e-12; x += 0.02) {
        if (first_ratio(x) > first_ratio(best)) best = x;
    }
    double a = best - 0.02, b = std::min(1.0, best + 0.02);
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 40; ++it) {
        const double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (first_ratio(x1) > first_ratio(x2)) {
            b = x2;
        } else {
            a = x1;
        }
    }
    const double x_star = 0.5 * (a + b);
    const double r_star = first_ratio(x_star);
    EXPECT_NEAR(x_star, 0.78, 0.01);
    EXPECT_NEAR(r_star, 6.27, 0.01);
    // Independent check of the peak value from the transfer determinant.
    const double exact = std::pow(closed_form::pinned_cantilever_beta_l(x_star) / closed_form::cantilever_beta_l(1)[0], 2);
    EXPECT_NEAR(r_star, exact, 1e-6);
    std::printf("ratio_1 max %.6f at x0/l = %.5f\n", r_star, x_star);
}

TEST(SupportScan, RatiosAtAGridOfPositions) {
    const Case c = test::paper_cantilever(50, 1.0);
    const auto pts = support_scan(c, {0.25, 0.5, 0.7834, 1.0}, 3, SupportModel::pin);
    ASSERT_EQ(pts.size(), 4u);
    for (const auto& p : pts) {
        ASSERT_EQ(p.study.ratios.size(), 3u);
        for (double r : p.study.ratios) EXPECT_GE(r, 1.0 - 1e-12) << "a pin never lowers a frequency";
    }
    // A pin at the tip: propped cantilever, beta l = 3.926602.
    EXPECT_NEAR(pts[3].study.ratios[0], std::pow(3.926602 / 1.875104, 2), 1e-5);
}

}  // namespace
}  // namespace vi
