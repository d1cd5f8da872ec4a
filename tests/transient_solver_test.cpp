// The contract both transient solvers keep (dynamics/transient_solver.hpp), each taken through the
// common interface: its name in the result, the work bounds of TransientOptions, the energy history
// on request, and one answer for one problem.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/exact/exact_solver.hpp"
#include "model/run_control.hpp"
#include "transient_fixtures.hpp"

namespace vi {
namespace {

// A two-element cantilever dropped on a tip support: a few impacts in 60 us.
TransientProblem drop() { return test::cantilever_drop(2, 40.0, 5e-7, 1e-6, 0.0, 0.0, 6e-5); }

std::vector<std::unique_ptr<TransientSolver>> both() {
    std::vector<std::unique_ptr<TransientSolver>> s;
    s.push_back(std::make_unique<ExactSolver>());
    CvodeOptions tight;
    tight.rtol = 1e-11;
    s.push_back(std::make_unique<CvodeSolver>(tight));
    return s;
}

TEST(TransientSolver, ResultNamesTheSolverAndBothAgreeOnTheImpacts) {
    const TransientProblem p = drop();
    std::vector<TransientResult> r;
    for (const auto& s : both()) {
        r.push_back(s->solve(p, {}));
        EXPECT_EQ(r.back().stats.method, std::string(s->method()));
        EXPECT_EQ(r.back().t_end, p.t_end);
        ASSERT_GE(r.back().episodes.size(), 2u) << s->method();
    }
    ASSERT_EQ(r[0].episodes.size(), r[1].episodes.size());
    for (std::size_t i = 0; i < r[0].episodes.size(); ++i) {
        EXPECT_NEAR(r[1].episodes[i].t_on, r[0].episodes[i].t_on, 1e-7 * r[0].episodes[i].t_on) << "episode " << i;
    }
}

TEST(TransientSolver, EnergyHistoryOnlyOnRequest) {
    const TransientProblem p = drop();
    for (const auto& s : both()) {
        TransientOptions o;
        o.energy = false;
        const TransientResult without = s->solve(p, o);
        EXPECT_TRUE(without.history.energy.empty()) << s->method();
        const TransientResult with = s->solve(p, {});
        EXPECT_EQ(with.history.energy.size(), with.history.t.size()) << s->method();
        EXPECT_FALSE(with.history.energy.empty()) << s->method();
    }
}

// The solver stops with WorkLimitReached naming `setting`.
void expect_work_limit(const TransientSolver& s, const TransientProblem& p, const TransientOptions& o,
                       const std::string& setting) {
    try {
        (void)s.solve(p, o);
        ADD_FAILURE() << s.method() << ": no WorkLimitReached for " << setting;
    } catch (const WorkLimitReached& e) {
        EXPECT_NE(std::string(e.what()).find(setting), std::string::npos) << e.what();
    }
}

TEST(TransientSolver, WorkBoundsNameTheSettingThatRaisesThem) {
    const TransientProblem p = drop();
    for (const auto& s : both()) {
        TransientOptions few_events;
        few_events.max_events = 1;
        expect_work_limit(*s, p, few_events, "solver.max_events");
        TransientOptions few_steps;
        few_steps.max_steps = 5;
        expect_work_limit(*s, p, few_steps, "solver.max_steps");
    }
}

}  // namespace
}  // namespace vi
