// The exact solver's history taken a run of samples at a time (PieceSolution::sample_many, the path
// without the energy ledger or field frames) against one sample at a time (PieceSolution::sample,
// the path a field frame takes): every channel the same to the last bit, with one and two supports,
// open and closed, and an open contact's force exactly 0.

#include <gtest/gtest.h>

#include <string>

#include "dynamics/exact/exact_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "io/case_reader.hpp"

namespace vi {
namespace {

TransientResult history_run(const std::string& example, double horizon, long field_every) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/" + example);
    if (horizon > 0.0) c.solver.horizon = horizon;  // else the example's own
    const BuiltProblem b = build_transient_problem(c);
    TransientOptions o;
    o.history = true;
    o.energy = false;
    o.field_every = field_every;  // > 0: every sample taken alone
    return solve_exact(b.problem, o);
}

void expect_same_history(const std::string& example, double horizon) {
    SCOPED_TRACE(example);
    const TransientResult runs = history_run(example, horizon, 0);
    const TransientResult single = history_run(example, horizon, 1L << 40);
    const TimeHistory& a = runs.history;
    const TimeHistory& b = single.history;
    ASSERT_GT(a.t.size(), 1000U);
    ASSERT_EQ(a.t, b.t);
    EXPECT_EQ(a.watched_v, b.watched_v);
    EXPECT_EQ(a.watched_velocity, b.watched_velocity);
    ASSERT_EQ(a.contact_v.size(), b.contact_v.size());
    for (std::size_t c = 0; c < a.contact_v.size(); ++c) {
        EXPECT_EQ(a.contact_v[c], b.contact_v[c]);
        EXPECT_EQ(a.contact_velocity[c], b.contact_velocity[c]);
        EXPECT_EQ(a.contact_force[c], b.contact_force[c]);
    }
    // Both closed and open samples on every support: the force channel is summed only when closed.
    for (std::size_t c = 0; c < a.contact_force.size(); ++c) {
        long closed = 0, open = 0;
        for (double f : a.contact_force[c]) (f != 0.0 ? closed : open) += 1;
        EXPECT_GT(closed, 10) << "support " << c;
        EXPECT_GT(open, 10) << "support " << c;
    }
}

TEST(HistorySamples, RunsOfSamplesEqualSingleSamplesWithOneSupport) {
    expect_same_history("paper/free_impact_tip.toml", 68.6443e-6);
}

TEST(HistorySamples, RunsOfSamplesEqualSingleSamplesWithTwoSupports) {
    expect_same_history("devices/bridge_relay.toml", 0.0);
}

}  // namespace
}  // namespace vi
