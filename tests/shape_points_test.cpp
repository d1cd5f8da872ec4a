// Nodal points and peaks of mode shapes against the closed-form cantilever shapes.

#include <gtest/gtest.h>

#include <cmath>

#include "validation/closed_forms.hpp"
#include "modal/modal_analysis.hpp"
#include "modal/shape_points.hpp"
#include "paper_cases.hpp"

namespace vi {
namespace {

TEST(CubicRoots, FindsSimpleDoubleAndEndRoots) {
    // (t - 0.2)(t - 0.5)(t - 0.9) = -0.09 + 0.73 t - 1.6 t^2 + t^3
    auto r = cubic_roots_in({-0.09, 0.73, -1.6, 1.0}, 0.0, 1.0);
    ASSERT_EQ(r.size(), 3u);
    EXPECT_NEAR(r[0], 0.2, 1e-14);
    EXPECT_NEAR(r[1], 0.5, 1e-14);
    EXPECT_NEAR(r[2], 0.9, 1e-14);
    // Two roots inside with equal signs at both ends: missed by a sign test at the ends alone.
    r = cubic_roots_in({0.1, -1.0, 1.0, 0.0}, 0.0, 1.0);  // t^2 - t + 0.1
    ASSERT_EQ(r.size(), 2u);
    EXPECT_NEAR(r[0], (1 - std::sqrt(0.6)) / 2, 1e-14);
    EXPECT_NEAR(r[1], (1 + std::sqrt(0.6)) / 2, 1e-14);
    r = cubic_roots_in({0.0, 1.0, 0.0, 0.0}, 0.0, 1.0);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0], 0.0);
    EXPECT_TRUE(cubic_roots_in({1.0, 0.0, 0.0, 0.0}, 0.0, 1.0).empty());
}

TEST(ShapePoints, CantileverNodalPointsMatchClosedForm) {
    const ModalResult r = analyse_modes(build_system(test::paper_cantilever(50)), 5);
    const std::vector<double> beta = closed_form::cantilever_beta_l(5);
    for (int i = 0; i < 5; ++i) {
        const std::vector<double> exact = closed_form::cantilever_shape_zeros(beta[i]);
        const std::vector<double>& fe = r.bending[i].features.nodes;
        ASSERT_EQ(fe.size(), static_cast<std::size_t>(i)) << "mode " << i + 1 << " has i nodal points";
        ASSERT_EQ(exact.size(), fe.size());
        for (std::size_t k = 0; k < fe.size(); ++k) EXPECT_NEAR(fe[k], exact[k], 1e-5) << "mode " << i + 1;
    }
    // The values the paper quotes (Table 1 of Ostasevicius et al. 2009).
    EXPECT_NEAR(r.bending[1].features.nodes[0], 0.7834, 1e-4);
    EXPECT_NEAR(r.bending[2].features.nodes[0], 0.5036, 1e-4);
    EXPECT_NEAR(r.bending[2].features.nodes[1], 0.8677, 1e-4);
}

TEST(ShapePoints, RotationNodesAreTheDisplacementPeaks) {
    const ModalResult r = analyse_modes(build_system(test::paper_cantilever(50)), 4);
    const std::vector<double> beta = closed_form::cantilever_beta_l(4);
    for (int i = 0; i < 4; ++i) {
        const Mode& m = r.bending[i];
        const std::vector<double> exact = closed_form::cantilever_slope_zeros(beta[i]);
        ASSERT_EQ(m.features.rotation_nodes.size(), exact.size()) << "mode " << i + 1;
        for (std::size_t k = 0; k < exact.size(); ++k) EXPECT_NEAR(m.features.rotation_nodes[k], exact[k], 1e-4);
        // Interior peaks of |v| sit where theta = 0; the last peak is the free end.
        ASSERT_EQ(m.features.peaks.size(), exact.size() + 1) << "mode " << i + 1;
        for (std::size_t k = 0; k < exact.size(); ++k) EXPECT_NEAR(m.features.peaks[k].x, exact[k], 1e-4);
        EXPECT_DOUBLE_EQ(m.features.peaks.back().x, 1.0);
        EXPECT_NEAR(m.features.peaks.back().amplitude, 2.0, 1e-5);
    }
    // Mode 3's peak between its nodal points: 0.6923 by the closed form (the paper quotes 0.67).
    EXPECT_NEAR(r.bending[2].features.peaks[1].x, 0.6923, 1e-4);
}

TEST(ShapePoints, PeakAmplitudesMatchClosedFormShape) {
    const Case c = test::paper_cantilever(50);
    const ModalResult r = analyse_modes(build_system(c), 3);
    const std::vector<double> beta = closed_form::cantilever_beta_l(3);
    for (int i = 0; i < 3; ++i) {
        // Closed-form shape scaled so that its tip is 2 (the mass-normalised value).
        const double scale = 2.0 / std::abs(closed_form::cantilever_shape(beta[i], 1.0));
        for (const ShapePeak& p : r.bending[i].features.peaks) {
            EXPECT_NEAR(p.amplitude, scale * std::abs(closed_form::cantilever_shape(beta[i], p.x)), 1e-5);
        }
        for (const ShapePeak& p : r.bending[i].features.rotation_peaks) {
            EXPECT_NEAR(p.amplitude, scale * std::abs(closed_form::cantilever_slope(beta[i], p.x)), 1e-3 * scale);
        }
    }
}

TEST(ShapePoints, ClampIsNotANodalPointButAPinnedSupportIs) {
    const ModalStudy st = modal_study(test::paper_cantilever(50, 0.6), 2, SupportModel::pin);
    const ShapeFeatures& f = st.supported.bending[0].features;
    ASSERT_FALSE(f.nodes.empty());
    EXPECT_GT(f.nodes.front(), 0.0);
    bool support_listed = false;
    for (double x : f.nodes) support_listed |= std::abs(x - 0.6) < 1e-12;
    EXPECT_TRUE(support_listed);
    for (const Mode& m : st.unsupported.bending) {
        for (double x : m.features.nodes) EXPECT_GT(x, 1e-6);
        for (double x : m.features.rotation_nodes) EXPECT_GT(x, 1e-6);
    }
}

TEST(ShapePoints, CoarseMeshFindsTwoZerosInsideOneElement) {
    // With m = 1 the single cubic element must still place mode 2's nodal point inside itself.
    const ModalResult r = analyse_modes(build_system(test::paper_cantilever(2)), 2);
    EXPECT_EQ(r.bending[1].features.nodes.size(), 1u);
}

}  // namespace
}  // namespace vi

namespace vi {
namespace {

TEST(ShapePoints, SupportAtTheFreeEndIsAlwaysANodalPoint) {
    // The pinned tip's zero comes from the constrained DOF itself, so no mesh may lose it.
    for (int m = 5; m <= 120; m += 23) {
        const ModalStudy st = modal_study(test::paper_cantilever(m, 1.0), 6, SupportModel::pin);
        for (const Mode& mode : st.supported.bending) {
            ASSERT_FALSE(mode.features.nodes.empty()) << "m " << m << " mode " << mode.number;
            EXPECT_EQ(mode.features.nodes.back(), 1.0) << "m " << m << " mode " << mode.number;
            for (const ShapePeak& p : mode.features.peaks) EXPECT_GT(p.amplitude, 1e-6) << "m " << m;
        }
    }
}

}  // namespace
}  // namespace vi
