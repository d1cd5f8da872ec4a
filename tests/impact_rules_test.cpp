// The impact rules side by side (docs/case-files.md, [solver]): episodes grouped by short flights or
// not at all, and T_p ended by peak penetration or by approach speed, on episodes made by hand.

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "case_text_fixture.hpp"
#include "impacts/impact_summary.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

ContactEpisode episode(double on, double off, double v_in, double penetration) {
    ContactEpisode e;
    e.t_on = on;
    e.t_off = off;
    e.v_in = v_in;
    e.v_out = -v_in / 2;
    e.peak_penetration = penetration;
    e.peak_force = penetration * 1e3;
    return e;
}

// Four episodes on one support: a bounce with a short chatter flight (1.1 -> 1.15), then two
// smaller impacts. omega1 = pi makes the default group gap a quarter period, 0.5 s.
TransientResult bouncing() {
    TransientResult r;
    r.episodes = {episode(1.0, 1.1, -1.0, 10e-9), episode(1.15, 1.2, -0.3, 2e-9), episode(3.0, 3.1, -0.5, 5e-9),
                  episode(5.0, 5.05, -0.01, 0.05e-9)};
    return r;
}

ImpactSettings settings() {
    ImpactSettings s;
    s.omega1 = std::numbers::pi;
    s.length = 1.0;
    return s;
}

TEST(ImpactRules, FlightsJoinEpisodesOrEveryEpisodeIsAnImpact) {
    const ImpactSummary grouped = summarize_impacts(bouncing(), settings());
    EXPECT_DOUBLE_EQ(grouped.group_gap, 0.5);
    ASSERT_EQ(grouped.impacts.size(), 3u);
    EXPECT_EQ(grouped.impacts[0].episodes, 2);
    EXPECT_DOUBLE_EQ(*grouped.T_first, 2.0);
    EXPECT_DOUBLE_EQ(*grouped.T1_first, 1.8);

    ImpactSettings none = settings();
    none.group = false;
    const ImpactSummary single = summarize_impacts(bouncing(), none);
    EXPECT_EQ(single.group_gap, 0.0);
    ASSERT_EQ(single.impacts.size(), 4u);
    EXPECT_DOUBLE_EQ(*single.T_first, 0.15);
    EXPECT_NEAR(*single.T1_first, 0.05, 1e-15);
}

TEST(ImpactRules, TpEndsByPenetrationOrByApproachSpeed) {
    ImpactSettings s = settings();
    s.settle_tolerance = 0.01;  // 0.1 nm: the 0.05 nm impact at t = 5 is below it
    const ImpactSummary pen = summarize_impacts(bouncing(), s);
    EXPECT_EQ(pen.Tp_reason, "settled");
    EXPECT_DOUBLE_EQ(*pen.Tp, 3.1);

    s.settle_by_velocity = true;
    s.settle_velocity = 0.4;  // the impacts at 1 m/s and 0.5 m/s count
    EXPECT_DOUBLE_EQ(*summarize_impacts(bouncing(), s).Tp, 3.1);
    s.settle_velocity = 0.6;  // only the first impact (its two episodes end at 1.2)
    const ImpactSummary fast = summarize_impacts(bouncing(), s);
    EXPECT_EQ(fast.Tp_reason, "settled");
    EXPECT_DOUBLE_EQ(*fast.Tp, 1.2);
    s.settle_velocity = 2.0;  // none: settled from the first contact on
    const ImpactSummary none = summarize_impacts(bouncing(), s);
    EXPECT_EQ(none.Tp_reason, "below_threshold");
    EXPECT_DOUBLE_EQ(*none.Tp, 1.0);
    s.settle_velocity = 0.005;  // every impact counts, the last too: the decay was not seen
    const ImpactSummary all = summarize_impacts(bouncing(), s);
    EXPECT_EQ(all.Tp_reason, "horizon");
    EXPECT_FALSE(all.Tp);
}

std::string error_of(const std::string& solver) {
    try {
        read_case_text(test::kBaseCase + "[solver]\n" + solver, "bad.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(ImpactRules, CaseFileKeysAndTheirRefusals) {
    const Case c = read_case_text(test::kBaseCase + "[solver]\ngrouping = \"none\"\nsettle_rule = \"velocity\"\n"
                                                    "settle_velocity = \"1 mm/s\"\n", "ok.toml");
    EXPECT_EQ(c.solver.grouping, SolverSettings::Grouping::none);
    EXPECT_EQ(c.solver.settle_rule, SolverSettings::SettleRule::velocity);
    EXPECT_DOUBLE_EQ(c.solver.settle_velocity, 1e-3);
    EXPECT_EQ(error_of("grouping = \"none\"\ngroup_gap = \"1 us\"\n"),
              "bad.toml:13: solver.group_gap: only with solver.grouping = \"flights\" (with \"none\" no episodes are joined)");
    EXPECT_EQ(error_of("settle_rule = \"velocity\"\n"), "bad.toml:11: solver.settle_velocity: missing required key");
    EXPECT_EQ(error_of("settle_velocity = \"1 m/s\"\n"),
              "bad.toml:12: solver.settle_velocity: only with solver.settle_rule = \"velocity\"");
    EXPECT_EQ(error_of("settle_rule = \"velocity\"\nsettle_velocity = \"-1 m/s\"\n"),
              "bad.toml:13: solver.settle_velocity: must be positive");
    EXPECT_EQ(error_of("grouping = \"episodes\"\n").substr(0, 35), "bad.toml:12: solver.grouping: must ");
}

}  // namespace
}  // namespace vi
