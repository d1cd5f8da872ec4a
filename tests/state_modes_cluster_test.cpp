// Contact states whose overdamped high modes crowd together: under stiffness-proportional damping the
// slow poles of the heavily overdamped modes all approach -1/beta, and a contact away from the free
// end couples them into a nearly defective cluster. The exact solver must still decompose these
// states exactly (no dense fallback, no failure) and agree with CVODE.

#include <gtest/gtest.h>

#include <cmath>

#include "impacts/simulation.hpp"
#include "dynamics/piecewise_linear_form.hpp"
#include "dynamics/transient_start.hpp"
#include "dynamics/exact/state_modes.hpp"
#include "io/case_reader.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace {

// The paper's free-impact example with its support at x0/l and the damper Cc of the free end.
Case example_at(double x0) {
    Case c = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    c.supports.front().position = x0;
    c.supports.front().damping_ratio.reset();
    c.supports.front().damping = 5e-5;
    c.solver.horizon = 100e-6;
    return c;
}

TEST(StateModesCluster, InteriorContactsDecomposeExactly) {
    // Before the structured secular solution (factored secular function, residues recomputed from
    // the computed roots) these fell back to a dense solve that failed.
    for (double x0 : {0.5, 0.536, 0.67, 0.87}) {
        const BuiltProblem b = build_transient_problem(example_at(x0));
        const PiecewiseLinearProblem p = piecewise_linear_form(b.problem);
        const BaseModes base = base_modes(p);
        const StateModes s = decompose_state(base, p, {true});
        EXPECT_EQ(s.method, "rank-one") << x0;
        EXPECT_LT(s.residual, 1e-6) << x0;
    }
}

TEST(StateModesCluster, CrowdedClusterRunAgreesWithCvode) {
    // Reference: the same case with solver.method = "cvode" (rtol 1e-10), an independent method, run
    // once (90 s) and recorded here; x0/l = 0.536 has the most crowded cluster of overdamped poles.
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    const SimulationRun run = run_simulation(example_at(0.536), o);
    const ImpactSummary& s = run.summary;
    ASSERT_TRUE(s.Tp);
    ASSERT_TRUE(s.y_max);
    ASSERT_GE(s.impacts.size(), 3u);
    EXPECT_EQ(s.impacts.size(), 17u);
    EXPECT_NEAR(*s.Tp, 9.499750854867179e-05, 1e-7 * 9.5e-5);
    EXPECT_NEAR(*s.y_max, 8.080021503776227e-07, 1e-7 * 8.08e-7);
    EXPECT_NEAR(s.impacts[2].t_on, 1.4166753601679794e-05, 1e-7 * 1.42e-5);
    EXPECT_NEAR(s.impacts[2].peak_force, 3.586457271341585e-05, 1e-6 * 3.59e-5);
}

}  // namespace
}  // namespace vi
