// The CVODE state in the FE DOFs (CvodeOptions::State::nodal) against the same full model in modal
// coordinates: the switching transient of the cantilever switch on a small mesh (closing time, every
// contact episode, stable contact), the energy ledger through impacts, the Newton solve itself, and
// which coordinates the automatic choice takes.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/cvode/cvode_system.hpp"
#include "dynamics/cvode/modal_basis.hpp"
#include "dynamics/cvode/physical_newton.hpp"
#include "dynamics/transient_start.hpp"
#include "impacts/simulation.hpp"
#include "impacts/switching_ledger.hpp"
#include "io/case_reader.hpp"

namespace vi {
namespace {

Case nodal_test_case(int elements) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch.toml");
    c.beam.elements = elements;
    return c;
}

struct NodalSwitchRun {
    TransientResult result;
    SwitchingLedger ledger;
};

NodalSwitchRun run_nodal_test_case(const Case& c, CvodeOptions::State state) {
    SimulationOptions so;
    so.history = false;
    so.energy = false;
    const BuiltProblem built = build_transient_problem(c);
    CvodeOptions o = cvode_options(c.solver);
    o.state = state;
    NodalSwitchRun r{solve_cvode(built.problem, transient_options(c.solver, so), o), {}};
    std::vector<LedgerContact> contacts;
    for (const auto& named : built.model.contacts) contacts.push_back({named.name, std::nullopt, std::nullopt});
    r.ledger = switching_ledger(r.result, c.electrodes, built.model.omega1, contacts);
    return r;
}

// The example's 50 us at 70 V on 20 elements, both ways at rtol 1e-10: 9 episodes, 8 bounces,
// stable contact at 23.42 us. The two differ by what each solver's tolerance leaves: measured
// relative differences in the closing time 5.7e-9, 9.5e-10, 3.1e-10 and in the episodes' onsets and
// ends 3.2e-6, 5.4e-7, 7.3e-8 at rtol 1e-8, 1e-9, 1e-10 (the chatter's short flights amplify the
// later onsets), peak forces 3.4e-5, 5.0e-6, 7.5e-7. The bounds are those at 1e-10 with a margin
// of about three.
TEST(CvodeNodalState, SwitchTransientMatchesTheModalFullModel) {
    Case c = nodal_test_case(20);
    c.solver.rtol = 1e-10;
    const NodalSwitchRun modal = run_nodal_test_case(c, CvodeOptions::State::modal);
    const NodalSwitchRun nodal = run_nodal_test_case(c, CvodeOptions::State::nodal);
    ASSERT_FALSE(modal.result.stats.nodal_state);
    ASSERT_TRUE(nodal.result.stats.nodal_state);
    EXPECT_EQ(nodal.result.stats.basis_vectors, modal.result.stats.basis_vectors);
    ASSERT_TRUE(modal.ledger.closing_time && nodal.ledger.closing_time);
    EXPECT_NEAR(*nodal.ledger.closing_time, *modal.ledger.closing_time, 1e-9 * *modal.ledger.closing_time);
    EXPECT_EQ(nodal.ledger.bounces, modal.ledger.bounces);
    EXPECT_GT(modal.ledger.bounces, 2);
    EXPECT_EQ(nodal.ledger.grouped_bounces, modal.ledger.grouped_bounces);
    ASSERT_TRUE(modal.ledger.stable_contact && nodal.ledger.stable_contact);
    EXPECT_NEAR(*nodal.ledger.stable_contact, *modal.ledger.stable_contact, 2e-7 * *modal.ledger.stable_contact);
    ASSERT_EQ(nodal.result.episodes.size(), modal.result.episodes.size());
    for (std::size_t k = 0; k < modal.result.episodes.size(); ++k) {
        const ContactEpisode& a = modal.result.episodes[k];
        const ContactEpisode& b = nodal.result.episodes[k];
        EXPECT_NEAR(b.t_on, a.t_on, 2e-7 * a.t_on) << "episode " << k;
        EXPECT_NEAR(b.t_off, a.t_off, 2e-7 * a.t_off) << "episode " << k;
        EXPECT_NEAR(b.peak_force, a.peak_force, 2e-6 * a.peak_force) << "episode " << k;
    }
}

// The automatic choice: the FE DOFs for the full model with an electrode over most of a mesh of at
// least 100 DOFs; modal coordinates on a smaller mesh, on a reduced model, and where the elements
// act on a few DOFs only (a point contact reads a few rows of the modal basis).
TEST(CvodeNodalState, AutomaticChoiceTakesTheFeDofsForADistributedForceOnAFineMesh) {
    const auto state = [](Case c) {
        c.solver.horizon = 0.2e-6;
        return run_nodal_test_case(c, CvodeOptions::State::automatic).result.stats.nodal_state;
    };
    EXPECT_TRUE(state(nodal_test_case(50)));
    EXPECT_FALSE(state(nodal_test_case(20)));
    Case reduced = nodal_test_case(50);
    reduced.solver.reduced_modes = 10;
    EXPECT_FALSE(state(reduced));
    Case point = nodal_test_case(50);
    point.electrodes.clear();
    point.loads.push_back(PointLoad{});
    point.loads.back().position = 1.0;
    point.loads.back().amplitude = -1e-6;
    EXPECT_FALSE(state(point));
}

// The nodal Newton solve (PhysicalNewton::solve_nodal) satisfies both block rows of
// (b I + a J) x = r with J the Jacobian of q' = v, v' = M^-1 (f - K q - C v), an electrode's
// tangent halfway down the gap, for steps from far below the first period to near the top mode's.
TEST(CvodeNodalState, NewtonSolveSatisfiesTheFirstOrderSystem) {
    const Case c = nodal_test_case(20);
    const BuiltProblem built = build_transient_problem(c);
    const TransientProblem& p = built.problem;
    cvode_detail::ModalSystem sys(p, nodal_basis(p.size()));
    const int n = p.size();
    Eigen::VectorXd y = sys.initial_state();
    y.head(n) += Eigen::VectorXd::Constant(n, -0.3e-6);
    sys.set_modes(sys.initial_modes(y.data()));
    Eigen::SparseMatrix<double> Fq, Fv;
    sys.fe_tangents(1e-7, y.data(), Fq, Fv);
    ASSERT_GT(Fq.nonZeros(), 3 * n);
    const Eigen::SparseMatrix<double> C = p.alpha * p.M + p.beta * p.K;
    cvode_detail::PhysicalNewton newton(sys);
    newton.set_tangents(Fq, Fv);
    std::mt19937 rng(11);
    std::normal_distribution<double> normal;
    for (const double gamma : {1e-12, 1e-9, 1e-7}) {
        const double a = -gamma, b = 1.0;
        ASSERT_TRUE(newton.factor(a, b));
        Eigen::VectorXd r_q(n), r_v(n);
        for (int k = 0; k < n; ++k) {
            r_q[k] = 1e-9 * normal(rng);
            r_v[k] = 1e-3 * normal(rng);
        }
        Eigen::VectorXd xv;
        newton.solve_nodal(r_q, r_v, xv);
        const Eigen::VectorXd xq = (r_q - a * xv) / b;
        // Row 2 times M: b M x_v + a ((Fq - K) x_q + (Fv - C) x_v) = M r_v.
        const Eigen::VectorXd lhs = b * (p.M * xv) + a * (Fq * xq - p.K * xq + Fv * xv - C * xv);
        const Eigen::VectorXd rhs = p.M * r_v;
        const double size = (b * (p.M * xv)).norm() + std::abs(a) * (p.K * xq).norm() + rhs.norm();
        EXPECT_LT((lhs - rhs).norm(), 1e-10 * size) << "gamma " << gamma;
    }
}

}  // namespace
}  // namespace vi
