// The exact event-driven solver against the independent CVODE solver on the default example.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/simulation.hpp"
#include "io/case_reader.hpp"

namespace vi {
namespace {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(SolverAgreement, DefaultExampleImpactOnsetsAndRebound) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    // Through the 10th impact (onset near 51 us); CVODE at rtol 1e-8 keeps this test near 25 s.
    c.solver.horizon = 53e-6;
    c.solver.output_step = 1e-6;
    c.solver.rtol = 1e-8;
    SimulationOptions o;
    o.energy = false;
    c.solver.method = SolverSettings::Method::exact;
    const SimulationRun exact = run_simulation(c, o);
    c.solver.method = SolverSettings::Method::cvode;
    const SimulationRun cvode = run_simulation(c, o);
    ASSERT_GE(exact.summary.impacts.size(), 10u);
    ASSERT_GE(cvode.summary.impacts.size(), 10u);
    double worst = 0.0;
    for (std::size_t i = 0; i < 10; ++i) {
        const double d = rel(cvode.summary.impacts[i].t_on, exact.summary.impacts[i].t_on);
        EXPECT_LT(d, 1e-6) << "impact " << i;
        EXPECT_EQ(cvode.summary.impacts[i].episodes, exact.summary.impacts[i].episodes) << "impact " << i;
        worst = std::max(worst, d);
    }
    ASSERT_TRUE(exact.summary.y_max && cvode.summary.y_max);
    EXPECT_LT(rel(*cvode.summary.y_max, *exact.summary.y_max), 1e-6);
    EXPECT_LT(rel(cvode.summary.impacts[0].peak_force, exact.summary.impacts[0].peak_force), 1e-5);
    std::printf("onsets agree to %.2e, y_max to %.2e\n", worst, rel(*cvode.summary.y_max, *exact.summary.y_max));
}

}  // namespace
}  // namespace vi
