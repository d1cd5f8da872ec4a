// `vibroimpact optimize` on several threads (design/design_store, the look-ahead of
// design/optimizer): the search uses the same designs in the same order, and finds the same best,
// on any number of threads; the threads compute designs the search asks for next.

#include <gtest/gtest.h>

#include <bit>
#include <cstdio>
#include <string>
#include <vector>

#include "design/optimizer.hpp"
#include "io/case_reader.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace {

DesignProblem paper_problem(const std::vector<std::string>& vary, const std::string& minimize,
                            const std::vector<std::string>& constraints = {}) {
    DesignProblem p;
    p.base = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    p.columns = sweep_result_columns(SweepAnalysis::simulate, 0);
    for (const std::string& v : vary) p.variables.push_back(parse_design_variable(v, p.base));
    p.objective = quantity_column(minimize, p.columns, "--minimize");
    for (const std::string& c : constraints) p.constraints.push_back(parse_design_constraint(c, p.columns));
    return p;
}

// The same evaluations bit for bit: stage, variables, status and every quantity.
void expect_same_search(const OptimizeResult& a, const OptimizeResult& b, const std::string& what) {
    ASSERT_EQ(a.evaluations.size(), b.evaluations.size()) << what;
    for (std::size_t i = 0; i < a.evaluations.size(); ++i) {
        const DesignEvaluation& ea = a.evaluations[i];
        const DesignEvaluation& eb = b.evaluations[i];
        EXPECT_EQ(ea.stage, eb.stage) << what << ", evaluation " << i;
        ASSERT_EQ(ea.x.size(), eb.x.size());
        for (std::size_t j = 0; j < ea.x.size(); ++j) {
            EXPECT_EQ(std::bit_cast<std::uint64_t>(ea.x[j]), std::bit_cast<std::uint64_t>(eb.x[j]))
                << what << ", evaluation " << i << ", variable " << j;
        }
        EXPECT_EQ(ea.outcome.status, eb.outcome.status) << what << ", evaluation " << i;
        EXPECT_EQ(ea.outcome.objective, eb.outcome.objective) << what << ", evaluation " << i;
        EXPECT_EQ(ea.outcome.constraints, eb.outcome.constraints) << what << ", evaluation " << i;
        EXPECT_EQ(ea.best, eb.best) << what << ", evaluation " << i;
    }
    EXPECT_EQ(a.best, b.best) << what;
    EXPECT_EQ(a.global_end, b.global_end) << what;
    EXPECT_EQ(a.local_end, b.local_end) << what;
}

// Both stages (DIRECT-L, then COBYLA under a constraint) on 1, 2 and 3 threads: the same search.
// On more threads the designs are computed in batches (the one the search needs and the next ones
// a look-ahead expects); a batch's first design is always used.
TEST(OptimizeThreads, TheSearchIsTheSameOnAnyNumberOfThreads) {
    const DesignProblem p = paper_problem({"supports[0].position=0.3:1", "supports[0].stiffness=100:10000"}, "z_max",
                                          {"impact1_peak_force_n<=5e-5"});
    OptimizeOptions o;
    o.max_evaluations = 30;
    o.threads = 1;
    const OptimizeResult one = optimize_design(p, o);
    EXPECT_EQ(one.threads, 1);
    EXPECT_EQ(one.unused_guesses, 0u);
    EXPECT_EQ(one.computed, one.evaluations.size());
    ASSERT_TRUE(one.best.has_value());
    for (const int threads : {2, 3}) {
        o.threads = threads;
        const OptimizeResult r = optimize_design(p, o);
        expect_same_search(one, r, std::to_string(threads) + " threads");
        EXPECT_EQ(r.threads, threads);
        EXPECT_EQ(r.computed, r.evaluations.size() + r.unused_guesses);
        EXPECT_LT(r.batches, r.evaluations.size());
        EXPECT_LE(r.computed, static_cast<std::size_t>(threads) * r.batches);
        std::printf("%d threads: %zu evaluations used, %zu computed in %zu batches (%zu guesses unused)\n", threads,
                    r.evaluations.size(), r.computed, r.batches, r.unused_guesses);
    }
}

// The one-variable search of the paper study (DIRECT-L, then BOBYQA) likewise.
TEST(OptimizeThreads, TheOneVariableSearchIsTheSameOnTwoThreads) {
    const DesignProblem p = paper_problem({"supports[0].position=0.3:1"}, "z_max");
    OptimizeOptions o;
    o.max_evaluations = 40;
    o.threads = 1;
    const OptimizeResult one = optimize_design(p, o);
    o.threads = 2;
    const OptimizeResult two = optimize_design(p, o);
    expect_same_search(one, two, "2 threads");
    // DIRECT-L's samples of one division lie where they lie whatever the values: the look-ahead
    // gets them right, and two designs run at once for most of the search.
    EXPECT_LE(two.batches, 0.75 * static_cast<double>(two.evaluations.size()));
    EXPECT_EQ(two.look_ahead_stopped_after, 0u);
    std::printf("2 threads: %zu evaluations used, %zu computed in %zu batches (%zu guesses unused)\n",
                two.evaluations.size(), two.computed, two.batches, two.unused_guesses);
}

}  // namespace
}  // namespace vi
