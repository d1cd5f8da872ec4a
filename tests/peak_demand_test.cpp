// Peaks on demand (TransientOptions::peak_level, impacts/peak_demand.hpp): a run that reads the
// peaks of its first impacts only reports what the run with every peak reports (T_p and its reason,
// the first cycle, the first three impacts, the extremes, every episode's times), and computes less.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "dynamics/signal/event_search.hpp"
#include "impacts/peak_demand.hpp"
#include "impacts/settled_stop.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"

namespace vi {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

SimulationRun summary_run(const Case& c, int peak_impacts, bool stop = false) {
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    o.peak_impacts = peak_impacts;
    if (stop) o.stop_when = [](const Case& k, const BuiltProblem& b) { return settled_stop(k, b, 3); };
    return run_simulation(c, o);
}

void expect_same_impact(const Impact& a, const Impact& b) {
    EXPECT_EQ(a.support, b.support);
    EXPECT_EQ(a.t_on, b.t_on);
    EXPECT_EQ(a.t_off, b.t_off);
    EXPECT_EQ(a.v_in, b.v_in);
    EXPECT_EQ(a.v_out, b.v_out);
    EXPECT_EQ(a.peak_force, b.peak_force);
    EXPECT_EQ(a.peak_penetration, b.peak_penetration);
    EXPECT_EQ(a.impulse, b.impulse);
    EXPECT_EQ(a.episodes, b.episodes);
}

// Returns how many episodes of `part` have no computed penetration peak.
int expect_same_summary(const SimulationRun& part, const SimulationRun& full, std::size_t leading = 3) {
    EXPECT_EQ(part.summary.Tp_reason, full.summary.Tp_reason);
    EXPECT_EQ(part.summary.Tp, full.summary.Tp);
    EXPECT_EQ(part.summary.T_first, full.summary.T_first);
    EXPECT_EQ(part.summary.T1_first, full.summary.T1_first);
    EXPECT_EQ(part.summary.T2_first, full.summary.T2_first);
    EXPECT_EQ(part.summary.y_max, full.summary.y_max);
    EXPECT_EQ(part.summary.y_max_contact, full.summary.y_max_contact);
    EXPECT_EQ(part.summary.watched_min, full.summary.watched_min);
    EXPECT_EQ(part.summary.impacts.size(), full.summary.impacts.size());
    for (std::size_t i = 0; i < leading && i < full.summary.impacts.size(); ++i) {
        expect_same_impact(part.summary.impacts.at(i), full.summary.impacts.at(i));
    }
    EXPECT_EQ(part.result.episodes.size(), full.result.episodes.size());
    int skipped = 0;
    for (std::size_t e = 0; e < part.result.episodes.size() && e < full.result.episodes.size(); ++e) {
        const ContactEpisode& a = part.result.episodes[e];
        const ContactEpisode& b = full.result.episodes[e];
        EXPECT_EQ(a.t_on, b.t_on);
        EXPECT_EQ(a.t_off, b.t_off);
        EXPECT_EQ(a.impulse, b.impulse);
        if (std::isnan(a.peak_penetration)) {
            ++skipped;
        } else if (std::isnan(a.peak_force)) {
            // Known only to lie above the settle threshold: a value the penetration reaches.
            EXPECT_LE(a.peak_penetration, b.peak_penetration * (1.0 + 1e-7));
        }
    }
    return skipped;
}

TEST(PeakDemand, LeadingImpactsRunReportsWhatTheFullRunReports) {
    const Case base = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    int skipped = 0;
    for (double x0 : {0.35, 0.6, 0.85, 1.0}) {
        for (double kc : {200.0, 3000.0}) {
            SCOPED_TRACE("x0/l = " + std::to_string(x0) + ", Kc = " + std::to_string(kc));
            Case c = base;
            c.supports.front().position = x0;
            c.supports.front().stiffness = kc;
            const SimulationRun full = summary_run(c, -1);
            const SimulationRun part = summary_run(c, 3);
            skipped += expect_same_summary(part, full);
            // Less work: the search's evaluations are counted.
            EXPECT_LE(part.result.stats.steps, full.result.stats.steps);
        }
    }
    EXPECT_GT(skipped, 20);
}

TEST(PeakDemand, SettledStopAndTwoSupportsAndChatter) {
    for (const char* file : {"/examples/devices/bridge_relay.toml", "/examples/devices/impact_sensor.toml",
                             "/examples/paper/free_impact_prestress.toml"}) {
        SCOPED_TRACE(file);
        const Case c = read_case_file(std::string(VI_SOURCE_DIR) + file);
        ASSERT_TRUE(c.electrodes.empty());
        const SimulationRun full = summary_run(c, -1);
        ASSERT_EQ(full.result.stats.method, "exact");
        expect_same_summary(summary_run(c, 3), full);
        expect_same_summary(summary_run(c, 1), full, 1);
    }
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    c.solver.horizon = 500e-6;
    expect_same_summary(summary_run(c, 3, true), summary_run(c, -1, true));
}

TEST(PeakDemand, VelocityRuleNeedsNoLaterPeaks) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    c.solver.settle_rule = SolverSettings::SettleRule::velocity;
    c.solver.settle_velocity = 0.05;
    const SimulationRun full = summary_run(c, -1);
    const SimulationRun part = summary_run(c, 3);
    EXPECT_GT(expect_same_summary(part, full), 10);
}

ContactEpisode episode(int support, double t_on, double t_off, double peak) {
    ContactEpisode e;
    e.support = support;
    e.t_on = t_on;
    e.t_off = t_off;
    e.peak_penetration = peak;
    return e;
}

// Settings whose grouping gap is `gap` (first period 2 pi) and whose settle threshold is 0.1 of
// the first impact's peak.
ImpactSettings grouping_settings(double gap) {
    ImpactSettings s;
    s.omega1 = 1.0;
    s.group_gap = gap;
    s.settle_tolerance = 0.1;
    return s;
}

TEST(PeakDemand, LevelFollowsTheSummarysGrouping) {
    ImpactSettings s = grouping_settings(1.0);
    auto level = leading_impacts_peak_level(s, 2);
    std::vector<ContactEpisode> eps;
    auto next = [&](ContactEpisode e) {
        eps.push_back(e);
        return level(eps);
    };
    EXPECT_EQ(next(episode(0, 0.0, 1.0, 5.0)), -kInf);   // impact 1
    EXPECT_EQ(next(episode(0, 1.5, 2.0, 8.0)), -kInf);   // within the gap: still impact 1
    EXPECT_EQ(next(episode(1, 2.5, 3.0, 1.0)), -kInf);   // impact 2, another support
    // Impact 3 on support 1: support 0's first impact could still take an episode, so no threshold yet.
    EXPECT_EQ(next(episode(1, 4.5, 5.0, 1.0)), -kInf);
    // Support 0 begins a new impact: the first impact is over, its peak 8: threshold 0.8.
    EXPECT_EQ(next(episode(0, 6.0, 7.0, 1.0)), 0.8);
    EXPECT_EQ(next(episode(0, 7.5, 8.0, 1.0)), 0.8);     // joins that impact (index 4)
    // Episodes handed over in another order make it start over, with the same answer.
    std::vector<ContactEpisode> again(eps.begin(), eps.end());
    EXPECT_EQ(level(again), 0.8);
    s.settle_by_velocity = true;
    auto by_speed = leading_impacts_peak_level(s, 1);
    std::vector<ContactEpisode> one{episode(0, 0.0, 1.0, 5.0)};
    EXPECT_EQ(by_speed(one), -kInf);
    one.push_back(episode(0, 3.0, 4.0, 1.0));
    EXPECT_EQ(by_speed(one), kInf);
}

TEST(PeakDemand, TiedOnsetsCountAsLeading) {
    const ImpactSettings s = grouping_settings(0.5);
    auto level = leading_impacts_peak_level(s, 1);
    std::vector<ContactEpisode> eps{episode(0, 1.0, 2.0, 4.0)};
    EXPECT_EQ(level(eps), -kInf);
    eps.push_back(episode(1, 1.0, 2.0, 3.0));  // the same onset at another support
    EXPECT_EQ(level(eps), -kInf);
    eps.push_back(episode(0, 3.0, 4.0, 1.0));
    eps.push_back(episode(1, 3.0, 4.0, 1.0));
    // Both first impacts are over; the summary's first may be either: the smaller peak, 3.
    EXPECT_DOUBLE_EQ(level(eps), 0.3);
}

// The comparison agrees with the full search on random signals: `below` only where the maximum is
// at or below the level, `above` only where the full search's maximum is above it.
TEST(PeakDemand, LevelComparisonAgreesWithTheFullSearch) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int outcomes[3] = {0, 0, 0};
    for (int trial = 0; trial < 40; ++trial) {
        Eigen::VectorXcd lambda(6);
        ExpSignal f;
        f.A.resize(6);
        for (int k = 0; k < 6; ++k) {
            const double w = 1e6 * (k + 1) * (1.0 + u(rng));
            lambda[k] = cd(-0.05 * w * u(rng), w);
            f.A[k] = std::polar(std::pow(10.0, -2.0 * u(rng)), 6.3 * u(rng));
        }
        f.lambda = &lambda;
        const double span = 1e-5;
        const double top = global_maximum(f, span, 64 * 2.2e-16, 1e-7, 1e-18).value;
        for (double ratio : {0.5, 0.999, 0.9999999, 1.0000001, 1.001, 2.0}) {
            const double level = top * ratio;
            const LevelComparison cmp = compare_with_level(f, span, level, 64 * 2.2e-16, 1e-7, 1e-18);
            ++outcomes[cmp.outcome];
            SCOPED_TRACE("trial " + std::to_string(trial) + ", level / maximum " + std::to_string(ratio));
            if (cmp.outcome == LevelComparison::below) {
                EXPECT_GE(level, top);
            }
            if (cmp.outcome == LevelComparison::above) {
                EXPECT_GT(top, level);
            }
            if (ratio <= 0.999) {
                EXPECT_EQ(cmp.outcome, LevelComparison::above);
            }
            if (ratio >= 1.001) {
                EXPECT_EQ(cmp.outcome, LevelComparison::below);
            }
        }
    }
    EXPECT_GT(outcomes[LevelComparison::undecided], 0);
}

}  // namespace
}  // namespace vi
