// The supported beam's first frequency peaks with the support near x0/l = 0.78 (paper Fig. 8).

#include <gtest/gtest.h>

#include <cmath>

#include "validation/closed_forms.hpp"
#include "validation/reference_problems.hpp"
#include "modal/support_scan.hpp"
#include "paper_cases.hpp"

namespace vi {
namespace {

TEST(SupportScan, FirstFrequencyRatioPeaksNear078At627) {
    const auto [x_star, r_star] = first_ratio_peak(50);
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
