// The cantilever's tip dropped on a Hertz dimple stiffer and stiffer tends to its impact on a rigid
// stop (the Kelvin-Voigt contact of Kc = 1e9 N/m on the exact solver, within 2e-12 s of Kc = 1e8 in
// T2), at the order the contact's own duration sets.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "forces/hertz_contact.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace rigid_limit_test {

struct Impact1 {
    double T = 0.0, T2 = 0.0, y_max = 0.0;
};

Impact1 first_impact(const Case& c) {
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    const SimulationRun r = run_simulation(c, o);
    EXPECT_TRUE(r.summary.T_first && r.summary.T2_first && r.summary.y_max);
    return {r.summary.T_first.value_or(0.0), r.summary.T2_first.value_or(0.0), r.summary.y_max.value_or(0.0)};
}

// The paper's free impact of the tip, undamped contact, through its first cycles.
Case paper_case() {
    Case c = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    c.solver.horizon = 30e-6;
    c.supports[0].damping_ratio.reset();
    c.supports[0].damping = 0.0;
    return c;
}

Case hertz(double effective_modulus) {
    Case c = paper_case();
    c.solver.method = SolverSettings::Method::cvode;
    c.solver.rtol = 1e-10;
    Support& s = c.supports[0];
    s.params.texts["law"] = "hertz";
    s.params.numbers["radius"] = 2e-6;
    s.params.numbers["effective_modulus"] = effective_modulus;
    return c;
}

// A dimple's contact lasts t_c = 2.9432 d_max / v with d_max ~ (m v^2 / k)^(2/5): its duration, and
// with it the impact's T2 over the rigid stop's, falls as k^(-2/5), by 100^(2/5) = 6.31 for each
// 100-fold E* (measured 6.6 from 100 x to 1e4 x gold's E*; 16 from 1 x to 100 x, where the contact
// is still as compliant as the beam's tip). T and y_max come closer faster (by 22 and 19 there).
// At 1e4 x gold's E* (480 TPa) the impact is the rigid stop's to 3e-6 in T and 7e-4 in T2 and y_max.
TEST(HertzRigidLimit, StiffDimpleTendsToTheRigidStopAtOrderTwoFifths) {
    Case rigid = paper_case();
    rigid.supports[0].stiffness = 1e9;  // 5e8 times the tip's own stiffness
    const Impact1 r = first_impact(rigid);
    const double gold = effective_modulus(79e9, 0.42, 79e9, 0.42);
    const Impact1 a = first_impact(hertz(100.0 * gold));
    const Impact1 b = first_impact(hertz(1e4 * gold));
    const double ratio = std::abs(a.T2 - r.T2) / std::abs(b.T2 - r.T2);
    std::printf("rigid T %.7g us T2 %.7g us y_max %.7g nm; 100 E*: T2 off by %.3g s; 1e4 E*: %.3g s; ratio %.3g "
                "(100^(2/5) = %.3g)\n",
                r.T * 1e6, r.T2 * 1e6, r.y_max * 1e9, a.T2 - r.T2, b.T2 - r.T2, ratio, std::pow(100.0, 0.4));
    EXPECT_GT(b.T2, r.T2);  // the compliant contact lengthens the impact
    EXPECT_NEAR(ratio, std::pow(100.0, 0.4), 0.2 * std::pow(100.0, 0.4));
    EXPECT_GT(std::abs(a.T - r.T) / std::abs(b.T - r.T), std::pow(100.0, 0.4));
    EXPECT_GT(std::abs(a.y_max - r.y_max) / std::abs(b.y_max - r.y_max), std::pow(100.0, 0.4));
    EXPECT_LT(std::abs(b.T - r.T), 1e-5 * r.T);
    EXPECT_LT(std::abs(b.T2 - r.T2), 1e-3 * r.T2);
    EXPECT_LT(std::abs(b.y_max - r.y_max), 1e-3 * r.y_max);
}

}  // namespace rigid_limit_test
}  // namespace vi
