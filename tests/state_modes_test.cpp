// Decompositions of contact states: the structured rank-one path against the dense eigen solve, at
// support positions inside the beam, and the conjugate-pair representation against the full one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "validation/reference_problems.hpp"
#include "dynamics/exact/secular.hpp"
#include "dynamics/exact/state_modes.hpp"
#include "fem/system.hpp"
#include "transient_fixtures.hpp"

namespace vi {
namespace {

// The paper cantilever with its contact moved to the node nearest to x/l = position.
PiecewiseLinearProblem with_contact_at(int m, double position, double beta) {
    PiecewiseLinearProblem p = test::cantilever_drop(m, 1000.0, 5e-5, 1e-6, 0.0, beta, 1e-5);
    const int node = static_cast<int>(std::lround(position * m));
    const System s = build_system(test::paper_cantilever(m, 1.0));
    const int reduced = s.reduced_of[static_cast<std::size_t>(global_dof(node, 1))];
    for (std::size_t i = 0; i < s.bending.size(); ++i) {
        if (s.bending[i] == reduced) p.contacts[0].dof = static_cast<int>(i);
    }
    return p;
}

// Eigenvalues of a decomposition, every conjugate written out, sorted for comparison.
std::vector<cd> all_eigenvalues(const Eigen::VectorXcd& lam) {
    std::vector<cd> v(lam.data(), lam.data() + lam.size());
    std::sort(v.begin(), v.end(), [](cd a, cd b) { return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag(); });
    return v;
}

TEST(StateModes, RankOneAgreesWithDenseAtInteriorSupports) {
    // Stiffness-proportional damping as in the examples: the slow poles of the overdamped modes
    // crowd near -1/beta, where the secular roots are hardest to separate.
    for (const double position : {0.28, 0.5, 0.68, 0.86, 1.0}) {
        const PiecewiseLinearProblem p = with_contact_at(50, position, 1.9e-9);
        const BaseModes b = base_modes(p);
        const StateModes s = decompose_state(b, p, {true});
        EXPECT_EQ(s.method, "rank-one") << position;
        EXPECT_LT(s.residual, 1e-10) << position;
        // Against a dense solve of A in [Omega eta; eta_dot] (A itself mixes 1 and omega^2 ~ 1e21,
        // and Eigen does not balance): every eigenvalue.
        const FullModes f = expand(s);
        const Eigen::MatrixXd A = state_matrix(b, p, {true});
        const int n = b.n;
        Eigen::MatrixXd As = Eigen::MatrixXd::Zero(2 * n, 2 * n);
        As.topRightCorner(n, n) = b.omega.asDiagonal();
        As.bottomLeftCorner(n, n) = A.bottomLeftCorner(n, n) * b.omega.cwiseInverse().asDiagonal();
        As.bottomRightCorner(n, n) = A.bottomRightCorner(n, n);
        const Eigen::VectorXcd dense = Eigen::EigenSolver<Eigen::MatrixXd>(As).eigenvalues();
        ASSERT_EQ(f.lambda.size(), dense.size());
        const std::vector<cd> d = all_eigenvalues(dense);
        const double top = f.lambda.cwiseAbs().maxCoeff();
        for (const cd z : all_eigenvalues(f.lambda)) {
            double nearest = 1e300;
            for (const cd w : d) nearest = std::min(nearest, std::abs(w - z));
            EXPECT_LT(nearest, 1e-8 * std::abs(z) + 1e-12 * top) << position << " " << z;
        }
        // L R = I over all 2n modes.
        const Eigen::MatrixXcd lr = f.L * f.R;
        EXPECT_LT((lr - Eigen::MatrixXcd::Identity(lr.rows(), lr.cols())).cwiseAbs().maxCoeff(), 1e-10) << position;
    }
}

TEST(StateModes, ConjugateRepresentativesGiveTheFullResponse) {
    const PiecewiseLinearProblem p = with_contact_at(20, 0.7, 1.9e-9);
    const BaseModes b = base_modes(p);
    for (const bool closed : {false, true}) {
        const StateModes s = decompose_state(b, p, {closed});
        const FullModes f = expand(s);
        Eigen::VectorXd x0(2 * b.n);
        for (int i = 0; i < x0.size(); ++i) x0[i] = std::sin(1.3 * i + 0.2) * (i < b.n ? 1e-9 : 1e-3);
        const Eigen::VectorXcd c = s.coordinates(x0);
        const Eigen::VectorXcd cf = f.L * x0.cast<cd>();
        for (const double t : {0.0, 1e-9, 3e-7, 2e-6}) {
            Eigen::VectorXcd e(s.size()), ef(f.lambda.size());
            for (int k = 0; k < s.size(); ++k) e[k] = std::exp(s.lambda[k] * t);
            for (int k = 0; k < f.lambda.size(); ++k) ef[k] = std::exp(f.lambda[k] * t);
            const Eigen::VectorXd x = s.state(c.cwiseProduct(e));
            const Eigen::VectorXcd xf = f.R * cf.cwiseProduct(ef);
            // Real to roundoff, and the same state.
            EXPECT_LT(xf.imag().cwiseAbs().maxCoeff(), 1e-12 * xf.real().cwiseAbs().maxCoeff() + 1e-300);
            for (int i = 0; i < x.size(); ++i) {
                const double scale = i < b.n ? xf.real().head(b.n).cwiseAbs().maxCoeff() : xf.real().tail(b.n).cwiseAbs().maxCoeff();
                EXPECT_NEAR(x[i], xf[i].real(), 1e-12 * scale) << "closed " << closed << " t " << t << " i " << i;
            }
        }
    }
}

TEST(StateModes, SecularRootsAreConjugateClosed) {
    const PiecewiseLinearProblem p = with_contact_at(20, 1.0, 1e-9);
    const BaseModes b = base_modes(p);
    const Eigen::VectorXd phi = b.phi.row(p.contacts[0].dof).transpose();
    std::vector<SecularMode> modes;
    for (int i = 0; i < b.n; ++i) {
        modes.push_back({phi[i] * phi[i], 2.0 * b.zeta[i] * b.omega[i], b.omega[i] * b.omega[i], b.pole_a[i], b.pole_b[i]});
    }
    ConjugateRoots r;
    ASSERT_TRUE(secular_roots(modes, 1000.0, 5e-5, r));
    std::size_t count = 0;
    for (std::size_t k = 0; k < r.z.size(); ++k) {
        count += r.paired[k] ? 2 : 1;
        if (r.paired[k]) EXPECT_GT(r.z[k].imag(), 0.0);
        else EXPECT_EQ(r.z[k].imag(), 0.0);
    }
    EXPECT_EQ(count, 2 * modes.size());
}

}  // namespace
}  // namespace vi
