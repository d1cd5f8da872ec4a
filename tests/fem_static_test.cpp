// Static deflections against closed forms: cantilever tip, clamped-clamped centre, axial end load.

#include <gtest/gtest.h>

#include <cmath>

#include "fem/system.hpp"
#include "paper_cases.hpp"

namespace vi {
namespace {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// Cubic elements are nodally exact for point loads, so what remains is roundoff, which grows with
// the condition number of K (about m^4): 5e-8 at m = 200 (docs/validation.md). Hence m <= 50 here.
TEST(FemStatic, CantileverTipDeflectionIsPl3Over3EI) {
    for (int m : {1, 7, 50}) {
        const Case c = test::paper_cantilever(m);
        const System s = build_system(c);
        const double P = 1e-6;
        const double l = c.beam.length;
        const Eigen::VectorXd q = solve_static(s, transverse_point_load(s, l, P));
        const double expected = P * l * l * l / (3.0 * c.material.youngs_modulus * c.beam.second_moment());
        EXPECT_LT(rel(transverse_displacement(s, q, l), expected), 1e-9) << "m = " << m;
    }
}

TEST(FemStatic, ClampedClampedCentreDeflectionIsPl3Over192EI) {
    for (int m : {2, 10, 50}) {
        const Case c = test::clamped_clamped(m);
        const System s = build_system(c);
        const double P = 1e-6;
        const double l = c.beam.length;
        const Eigen::VectorXd q = solve_static(s, transverse_point_load(s, 0.5 * l, P));
        const double expected = P * l * l * l / (192.0 * c.material.youngs_modulus * c.beam.second_moment());
        EXPECT_LT(rel(transverse_displacement(s, q, 0.5 * l), expected), 1e-9) << "m = " << m;
    }
}

TEST(FemStatic, LoadBetweenNodesGivesExactNodalDeflections) {
    // Cantilever, force at a = 0.3137 l (inside an element): tip deflection P a^2 (3l - a) / (6EI).
    const Case c = test::paper_cantilever(10);
    const System s = build_system(c);
    const double l = c.beam.length, a = 0.3137 * l, P = 2e-6;
    const Eigen::VectorXd q = solve_static(s, transverse_point_load(s, a, P));
    const double EI = c.material.youngs_modulus * c.beam.second_moment();
    EXPECT_LT(rel(transverse_displacement(s, q, l), P * a * a * (3 * l - a) / (6 * EI)), 1e-9);
}

TEST(FemStatic, AxialEndLoadStretchesByPlOverEA) {
    const Case c = test::paper_cantilever(13);
    const System s = build_system(c);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(s.size());
    const int last = s.mesh.node_count() - 1;
    f[s.reduced_of[global_dof(last, 0)]] = 1e-3;
    const Eigen::VectorXd q = solve_static(s, f);
    const double expected = 1e-3 * c.beam.length / (c.material.youngs_modulus * c.beam.area());
    EXPECT_LT(rel(q[s.reduced_of[global_dof(last, 0)]], expected), 1e-9);
}

TEST(FemStatic, PlateModulusStiffensByOneOverOneMinusNuSquared) {
    Case c = test::paper_cantilever(20);
    c.material.plate_modulus = true;
    const System s = build_system(c);
    const double l = c.beam.length, P = 1e-6;
    const Eigen::VectorXd q = solve_static(s, transverse_point_load(s, l, P));
    const double E = c.material.youngs_modulus / (1 - 0.31 * 0.31);
    EXPECT_LT(rel(transverse_displacement(s, q, l), P * l * l * l / (3 * E * c.beam.second_moment())), 1e-9);
}

TEST(FemMesh, SupportGetsItsOwnNodeExactly) {
    const Case c = test::paper_cantilever(50, 0.7834);
    const System s = build_system(c);
    ASSERT_EQ(s.mesh.support_nodes.size(), 1u);
    EXPECT_EQ(s.mesh.node_count(), 52);
    EXPECT_DOUBLE_EQ(s.mesh.x[s.mesh.support_nodes[0]], 0.7834 * c.beam.length);
    for (int e = 0; e < s.mesh.element_count(); ++e) EXPECT_GT(s.mesh.element_length(e), 0.0);
}

TEST(FemMesh, SupportOnAGridNodeAddsNoNode) {
    const System s = build_system(test::paper_cantilever(50, 0.5));
    EXPECT_EQ(s.mesh.node_count(), 51);
    EXPECT_EQ(s.mesh.support_nodes[0], 25);
}

// A support within a tenth of an element of an interior grid node takes that node instead of a
// sliver element beside it; near an end, or on a node another support took, it gets its own node.
TEST(FemMesh, SupportNearAGridNodeMovesItInsteadOfAddingASliver) {
    const Case c = test::paper_cantilever(16, 0.934);  // 0.056 of an element below node 15
    const System s = build_system(c);
    EXPECT_EQ(s.mesh.node_count(), 17);
    EXPECT_EQ(s.mesh.support_nodes[0], 15);
    EXPECT_DOUBLE_EQ(s.mesh.x[15], 0.934 * c.beam.length);
    const double h = c.beam.length / 16;
    for (int e = 0; e < s.mesh.element_count(); ++e) EXPECT_GT(s.mesh.element_length(e), 0.9 * h) << e;

    Case two = c;
    two.supports.push_back(two.supports[0]);
    two.supports[1].position = 0.9395;  // near node 15 too, which the first support took
    two.supports[1].side = Side::above;
    const System s2 = build_system(two);
    EXPECT_EQ(s2.mesh.node_count(), 18);
    EXPECT_DOUBLE_EQ(s2.mesh.x[s2.mesh.support_nodes[1]], 0.9395 * c.beam.length);

    const System near_end = build_system(test::paper_cantilever(16, 0.995));  // the free end is not moved
    EXPECT_EQ(near_end.mesh.node_count(), 18);
    EXPECT_EQ(near_end.mesh.x.back(), c.beam.length);
}

TEST(FemSystem, PinnedSupportRemovesItsTransverseDof) {
    const Case c = test::paper_cantilever(50, 0.7834);
    EXPECT_EQ(build_system(c, SupportModel::none).size(), 3 * 52 - 3);
    const System pinned = build_system(c, SupportModel::pin);
    EXPECT_EQ(pinned.size(), 3 * 52 - 4);
    EXPECT_EQ(pinned.support_dof[0], -1);
}

TEST(FemSystem, MassMatrixCarriesTheBeamMass) {
    // A uniform rigid translation in v (all v = 1, theta = 0) has kinetic mass rho A l; free-free
    // is not a valid case, so assemble the clamped system and add the clamped node's share by hand.
    const Case c = test::paper_cantilever(17);
    const System s = build_system(c);
    Eigen::VectorXd ones = Eigen::VectorXd::Zero(s.size());
    for (int n = 0; n < s.mesh.node_count(); ++n) {
        const int r = s.reduced_of[global_dof(n, 1)];
        if (r >= 0) ones[r] = 1.0;
    }
    const double L = s.mesh.element_length(0);
    const double rhoA = c.material.density * c.beam.area();
    // Missing from the reduced M: the clamped node's row/column of element 0 (156 + 2*54) rhoAL/420.
    const double clamped_share = rhoA * L * (156.0 + 2.0 * 54.0) / 420.0;
    EXPECT_LT(rel(ones.dot(s.M * ones) + clamped_share, rhoA * c.beam.length), 1e-12);
}

}  // namespace
}  // namespace vi
