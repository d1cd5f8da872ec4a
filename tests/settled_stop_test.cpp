// A run that stops once its settling is decided (impacts/settled_stop.hpp) reports what the run to
// the horizon reports: T_p and its reason, the first cycle, the first three impacts, the extremes.

#include <gtest/gtest.h>

#include <string>

#include "impacts/settled_stop.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"

namespace vi {
namespace {

Case free_impact_at(double x0) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    c.beam.elements = 10;
    c.solver.horizon = 500e-6;  // the paper study's: far past T_p at every support position
    c.supports.front().position = x0;
    return c;
}

SimulationRun summary_run(const Case& c, bool stop) {
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    if (stop) o.stop_when = [](const Case& k, const BuiltProblem& b) { return settled_stop(k, b, 3); };
    return run_simulation(c, o);
}

void expect_same_impact(const Impact& a, const Impact& b) {
    EXPECT_EQ(a.t_on, b.t_on);
    EXPECT_EQ(a.t_off, b.t_off);
    EXPECT_EQ(a.v_in, b.v_in);
    EXPECT_EQ(a.peak_force, b.peak_force);
    EXPECT_EQ(a.peak_penetration, b.peak_penetration);
    EXPECT_EQ(a.episodes, b.episodes);
}

TEST(SettledStop, EndsEarlyWithTheFullRunsSettlingAtEachSupportPosition) {
    for (double x0 : {0.45, 0.75, 1.0}) {
        SCOPED_TRACE("x0/l = " + std::to_string(x0));
        const Case c = free_impact_at(x0);
        const SimulationRun full = summary_run(c, false);
        const SimulationRun cut = summary_run(c, true);
        ASSERT_EQ(full.summary.Tp_reason, "settled");
        EXPECT_LT(cut.result.t_end, 0.8 * c.solver.horizon);
        EXPECT_GT(cut.result.t_end, *full.summary.Tp);
        EXPECT_LT(cut.summary.impacts.size(), full.summary.impacts.size());
        EXPECT_EQ(cut.summary.Tp_reason, full.summary.Tp_reason);
        EXPECT_EQ(cut.summary.Tp, full.summary.Tp);
        EXPECT_EQ(cut.summary.T_first, full.summary.T_first);
        EXPECT_EQ(cut.summary.T1_first, full.summary.T1_first);
        EXPECT_EQ(cut.summary.T2_first, full.summary.T2_first);
        for (std::size_t i = 0; i < 3; ++i) expect_same_impact(cut.summary.impacts.at(i), full.summary.impacts.at(i));
        EXPECT_EQ(cut.summary.z_max, full.summary.z_max);
        EXPECT_EQ(cut.summary.watched_min, full.summary.watched_min);
        EXPECT_EQ(cut.summary.y_max_contact, full.summary.y_max_contact);
    }
}

// The hook itself: the run ends at the start of the first piece the test accepts, and its history
// ends there too.
TEST(SettledStop, StopWhenEndsTheExactRunAndItsHistoryThere) {
    const Case c = free_impact_at(1.0);
    SimulationOptions o;
    o.energy = false;
    o.stop_when = [](const Case&, const BuiltProblem&) { return [](const RunSoFar& r) { return r.t > 20e-6; }; };
    const SimulationRun run = run_simulation(c, o);
    EXPECT_GT(run.result.t_end, 20e-6);
    EXPECT_LT(run.result.t_end, 30e-6);  // a piece lasts at most a flight, half a period of about 9 us
    ASSERT_FALSE(run.result.history.t.empty());
    EXPECT_LE(run.result.history.t.back(), run.result.t_end);
    for (const ContactEpisode& e : run.result.episodes) EXPECT_LE(e.t_off, run.result.t_end);
}

// No energy bound where a force is not a Kelvin-Voigt support (an electrode) or a load acts.
TEST(SettledStop, NoTestForACaseWithAnElectrode) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch.toml");
    c.beam.elements = 10;
    EXPECT_FALSE(settled_stop(c, build_transient_problem(c)));
}

}  // namespace
}  // namespace vi
