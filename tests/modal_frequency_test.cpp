// Natural frequencies against Euler-Bernoulli closed forms, convergence order, solver agreement.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "validation/closed_forms.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/modal_analysis.hpp"
#include "paper_cases.hpp"

namespace vi {
namespace {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

double exact_omega(const Case& c, double beta_l) {
    return closed_form::bending_omega(beta_l, c.material.effective_modulus(), c.beam.second_moment(),
                                      c.material.density, c.beam.area(), c.beam.length);
}

TEST(ClosedForm, BetaLMatchesTabulatedValues) {
    const std::vector<double> cf = closed_form::cantilever_beta_l(5);
    const double table[5] = {1.875104, 4.694091, 7.854757, 10.995541, 14.137168};
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(cf[i], table[i], 1e-6);
    const std::vector<double> cc = closed_form::clamped_clamped_beta_l(3);
    const double table_cc[3] = {4.730041, 7.853205, 10.995608};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(cc[i], table_cc[i], 1e-6);
}

TEST(ModalFrequency, CantileverMatchesEulerBernoulliAtM50) {
    const Case c = test::paper_cantilever(50);
    const ModalResult r = analyse_modes(build_system(c), 5);
    const std::vector<double> beta = closed_form::cantilever_beta_l(5);
    const double limit[5] = {1e-8, 1e-7, 1e-6, 3e-6, 1e-5};
    ASSERT_EQ(r.bending.size(), 5u);
    for (int i = 0; i < 5; ++i) {
        const double err = rel(r.bending[i].omega, exact_omega(c, beta[i]));
        EXPECT_LT(err, limit[i]) << "mode " << i + 1;
        EXPECT_GT(r.bending[i].omega, exact_omega(c, beta[i]) * (1 - 1e-13)) << "consistent mass bounds from above";
    }
}

TEST(ModalFrequency, ConvergesWithOrderFourInM) {
    const Case c10 = test::paper_cantilever(10);
    const Case c20 = test::paper_cantilever(20);
    const std::vector<double> beta = closed_form::cantilever_beta_l(3);
    const ModalResult r10 = analyse_modes(build_system(c10), 3);
    const ModalResult r20 = analyse_modes(build_system(c20), 3);
    for (int i = 0; i < 3; ++i) {
        const double e10 = rel(r10.bending[i].omega, exact_omega(c10, beta[i]));
        const double e20 = rel(r20.bending[i].omega, exact_omega(c20, beta[i]));
        const double order = std::log2(e10 / e20);
        EXPECT_NEAR(order, 4.0, 0.15) << "mode " << i + 1 << ": e10 = " << e10 << ", e20 = " << e20;
    }
}

TEST(ModalFrequency, ClampedClampedMatchesEulerBernoulli) {
    const Case c = test::clamped_clamped(50);
    const ModalResult r = analyse_modes(build_system(c), 3);
    const std::vector<double> beta = closed_form::clamped_clamped_beta_l(3);
    const double limit[3] = {1e-7, 1e-6, 3e-6};
    for (int i = 0; i < 3; ++i) EXPECT_LT(rel(r.bending[i].omega, exact_omega(c, beta[i])), limit[i]) << i + 1;
}

TEST(ModalFrequency, ThirdOverFirstIs17point55) {
    const ModalResult r = analyse_modes(build_system(test::paper_cantilever(50)), 3);
    EXPECT_NEAR(r.bending[2].omega / r.bending[0].omega, 17.547, 5e-3);
}

TEST(ModalFrequency, CantileverAxialModesConvergeToRodFrequencies) {
    // Clamped-free rod: omega_n = (2n - 1) pi / 2 sqrt(E / rho) / l; linear elements converge as h^2.
    const Case c = test::paper_cantilever(200);
    const ModalResult r = analyse_modes(build_system(c), 2);
    const double a = std::sqrt(c.material.youngs_modulus / c.material.density) / c.beam.length;
    EXPECT_LT(rel(r.axial[0].omega, std::numbers::pi / 2 * a), 1e-5);
    EXPECT_LT(rel(r.axial[1].omega, 3 * std::numbers::pi / 2 * a), 1e-4);
}

TEST(ModalFrequency, DenseAndLanczosSolversAgree) {
    const System s = build_system(test::paper_cantilever(50));
    const SparseMatrix K = submatrix(s.K, s.bending);
    const SparseMatrix M = submatrix(s.M, s.bending);
    const ModeSet dense = all_modes_dense(K, M);
    const ModeSet lanczos = lowest_modes_sparse(K, M, 6);
    for (int i = 0; i < 6; ++i) {
        EXPECT_LT(rel(lanczos.omega[i], dense.omega[i]), 1e-9);
        EXPECT_LT((lanczos.shapes.col(i) - dense.shapes.col(i)).norm(), 1e-6 * dense.shapes.col(i).norm());
    }
}

// The frequencies-only path gives the frequencies of the full one. At m = 20 both take the dense
// solution and at m = 120 both Lanczos: the same arithmetic, to 1e-12. At m = 50 the frequencies
// come from Lanczos (a few modes of a larger problem) and the modes from the dense solution: two
// solvers, each within roundoff of the exact eigenvalues (eps cond(K), about 1e-10 here), so to the
// 1e-9 of DenseAndLanczosSolversAgree.
TEST(ModalFrequency, FrequenciesAloneMatchTheModes) {
    for (const int m : {20, 50, 120}) {
        const System s = build_system(test::paper_cantilever(m));
        const SparseMatrix K = submatrix(s.K, s.bending);
        const SparseMatrix M = submatrix(s.M, s.bending);
        const ModeSet modes = lowest_modes(K, M, 4);
        const Eigen::VectorXd omega = lowest_frequencies(K, M, 4);
        const double tolerance = m == 50 ? 1e-9 : 1e-12;
        ASSERT_EQ(omega.size(), 4) << "m = " << m;
        for (int i = 0; i < 4; ++i) EXPECT_LT(rel(omega[i], modes.omega[i]), tolerance) << "m = " << m << ", mode " << i;
    }
}

// The dense solution without its eigenvectors runs the same reduction and the same tridiagonal
// iteration on the eigenvalues: every frequency equal to the last bit, pinned or free.
TEST(ModalFrequency, DenseFrequenciesAloneAreThoseOfTheModes) {
    for (const SupportModel model : {SupportModel::none, SupportModel::pin}) {
        const Case c = test::paper_cantilever(50, 0.73);
        const System s = build_system(c, model);
        const SparseMatrix K = submatrix(s.K, s.bending);
        const SparseMatrix M = submatrix(s.M, s.bending);
        const Eigen::VectorXd omega = all_frequencies_dense(K, M);
        const ModeSet modes = all_modes_dense(K, M);
        ASSERT_EQ(omega.size(), modes.omega.size());
        for (Eigen::Index i = 0; i < omega.size(); ++i) EXPECT_EQ(omega[i], modes.omega[i]) << "mode " << i + 1;
    }
}

// The lowest few shapes formed alone (a modal scan's), the others formed later on the same
// matrices, and every shape formed at once all give the same numbers, to the last bit.
TEST(ModalShape, ShapesFormedInPartsAreThoseFormedAtOnce) {
    const System s = build_system(test::paper_cantilever(50, 0.61), SupportModel::pin);
    const SparseMatrix K = submatrix(s.K, s.bending);
    const SparseMatrix M = submatrix(s.M, s.bending);
    const System other = build_system(test::paper_cantilever(20));
    const ModeSet few = lowest_modes(K, M, 3);
    const ModeSet rest = all_modes_dense(K, M);
    (void)lowest_modes(submatrix(other.K, other.bending), submatrix(other.M, other.bending), 2);  // another problem in between
    const ModeSet once = all_modes_dense(K, M);
    ASSERT_EQ(few.shapes.cols(), 3);
    ASSERT_EQ(once.shapes.cols(), K.rows());
    EXPECT_TRUE(few.shapes == once.shapes.leftCols(3));
    EXPECT_TRUE(few.omega == once.omega.head(3));
    EXPECT_TRUE(rest.shapes == once.shapes);
    EXPECT_TRUE(rest.omega == once.omega);
}

// Past m ~ 100 the discretisation error (h^4) falls below roundoff, which grows like cond(K) ~ m^4:
// at m = 400 both solvers sit about 1e-7..1e-6 from the closed form (docs/validation.md).
TEST(ModalFrequency, LargeMeshUsesLanczosAndAgreesWithDense) {
    const Case c = test::paper_cantilever(400);
    const System s = build_system(c);
    ASSERT_GT(static_cast<int>(s.bending.size()), kDenseEigenLimit);
    const ModalResult r = analyse_modes(s, 3);
    const ModeSet dense = all_modes_dense(submatrix(s.K, s.bending), submatrix(s.M, s.bending));
    const std::vector<double> beta = closed_form::cantilever_beta_l(3);
    for (int i = 0; i < 3; ++i) {
        EXPECT_LT(rel(r.bending[i].omega, dense.omega[i]), 1e-6);
        EXPECT_LT(rel(r.bending[i].omega, exact_omega(c, beta[i])), 1e-6);
    }
}

TEST(ModalShape, MassNormalisedTipAmplitudeIsTwo) {
    // A cantilever's mass-normalised modes all have |phi(l)| sqrt(rho A l) = 2.
    const Case c = test::paper_cantilever(50);
    const ModalResult r = analyse_modes(build_system(c), 4);
    for (const Mode& m : r.bending) {
        const double tip = m.shape[global_dof(50, 1)] * std::sqrt(c.material.density * c.beam.area() * c.beam.length);
        EXPECT_NEAR(std::abs(tip), 2.0, 1e-5) << "mode " << m.number;
    }
}

TEST(SupportedModes, PinnedFirstFrequencyMatchesTransferDeterminant) {
    for (double a : {0.3, 0.7834, 0.87, 1.0}) {
        const Case c = test::paper_cantilever(50, a);
        const ModalStudy st = modal_study(c, 1, SupportModel::pin);
        const double exact = exact_omega(c, closed_form::pinned_cantilever_beta_l(a));
        EXPECT_LT(rel(st.supported.bending[0].omega, exact), 1e-7) << "a = " << a;
    }
}

TEST(SupportedModes, StiffSpringApproachesThePin) {
    Case c = test::paper_cantilever(50, 0.6);
    c.supports[0].stiffness = 1e9;
    const double pin = modal_study(c, 1, SupportModel::pin).supported.bending[0].omega;
    const double spring = modal_study(c, 1, SupportModel::spring).supported.bending[0].omega;
    EXPECT_LT(spring, pin);
    EXPECT_LT(rel(spring, pin), 1e-5);
}

}  // namespace
}  // namespace vi
