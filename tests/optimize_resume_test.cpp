// Stopping and resuming `vibroimpact optimize` (design/design_journal, the known designs of
// design/optimizer): the journal keeps every computed design exactly, refuses another problem's
// journal, drops a torn last line; a search stopped after k designs and resumed from them uses the
// same designs in the same order and ends with the same best as an uninterrupted one, in the
// library and through the command with SIGINT.

#include <gtest/gtest.h>
#include <signal.h>

#include <bit>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "design/design_journal.hpp"
#include "design/optimizer.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

DesignProblem paper_problem(const std::vector<std::string>& vary, const std::vector<std::string>& constraints = {}) {
    DesignProblem p;
    p.base = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    p.columns = sweep_result_columns(SweepAnalysis::simulate, 0);
    for (const std::string& v : vary) p.variables.push_back(parse_design_variable(v, p.base));
    p.objective = quantity_column("z_max", p.columns, "--minimize");
    for (const std::string& c : constraints) p.constraints.push_back(parse_design_constraint(c, p.columns));
    return p;
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

void expect_same_search(const OptimizeResult& a, const OptimizeResult& b, const std::string& what) {
    ASSERT_EQ(a.evaluations.size(), b.evaluations.size()) << what;
    for (std::size_t i = 0; i < a.evaluations.size(); ++i) {
        const DesignEvaluation& ea = a.evaluations[i];
        const DesignEvaluation& eb = b.evaluations[i];
        EXPECT_EQ(ea.stage, eb.stage) << what << ", evaluation " << i;
        for (std::size_t j = 0; j < ea.x.size(); ++j) EXPECT_EQ(bits(ea.x[j]), bits(eb.x[j])) << what << ", " << i;
        EXPECT_EQ(ea.outcome.status, eb.outcome.status) << what << ", evaluation " << i;
        EXPECT_EQ(ea.outcome.objective, eb.outcome.objective) << what << ", evaluation " << i;
        EXPECT_EQ(ea.outcome.constraints, eb.outcome.constraints) << what << ", evaluation " << i;
    }
    EXPECT_EQ(a.best, b.best) << what;
    EXPECT_EQ(a.local_end, b.local_end) << what;
}

// A search stopped once it has used k designs (in the global stage on one thread, in the local one
// on two), its computed designs then given back as known: the same search, and none of them
// computed again.
TEST(OptimizeResume, AStoppedSearchGoesOnFromItsDesignsToTheSameResult) {
    const DesignProblem p = paper_problem({"supports[0].position=0.3:1", "supports[0].stiffness=100:10000"},
                                          {"impact1_peak_force_n<=5e-5"});
    OptimizeOptions o;
    o.max_evaluations = 40;
    o.threads = 1;
    const OptimizeResult reference = optimize_design(p, o);
    ASSERT_GT(reference.evaluations.size(), 30u);
    for (const auto& [threads, k] : {std::pair<int, std::size_t>{1, 7}, {2, 28}}) {
        const std::size_t stop_at = k;  // a lambda captures a plain variable (not a structured binding)
        const std::string what = std::to_string(threads) + " threads, stopped after " + std::to_string(k);
        std::vector<ComputedDesign> saved;
        OptimizeOptions first = o;
        first.threads = threads;
        first.computed = [&saved](const ComputedDesign& d) { saved.push_back(d); };
        EXPECT_THROW(optimize_design(p, first,
                                     [stop_at](const DesignEvaluation& e) {
                                         if (e.index + 1 == stop_at) throw StopRequested(SIGINT);
                                     }),
                     StopRequested)
            << what;
        EXPECT_GE(saved.size(), k) << what;
        OptimizeOptions second = o;
        second.threads = threads;
        second.known = saved;
        const OptimizeResult r = optimize_design(p, second);
        expect_same_search(reference, r, what);
        EXPECT_GE(r.reused, k) << what;
        EXPECT_EQ(r.reused + r.computed - r.unused_guesses, r.evaluations.size()) << what;
    }
}

class OptimizeJournal : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = test::make_temp_dir();
        p_ = paper_problem({"supports[0].position=0.3:1", "supports[0].stiffness=100:10000"},
                           {"impact1_peak_force_n<=5e-5", "T_s>=1e-6"});
        identity_ = design_identity_text("case text", p_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    [[nodiscard]] std::string path() const { return dir_ + "/out/" + DesignJournal::kFileName; }

    std::string dir_;
    DesignProblem p_;
    std::string identity_;
};

// Written and read back: the variables bit for bit (-0 and subnormals included), the values exactly,
// missing values and a failed design's status with its commas.
TEST_F(OptimizeJournal, KeepsEveryDesignExactly) {
    std::vector<ComputedDesign> designs(3);
    designs[0] = {{0.1 + 0.2, 1e-300 * 1e-10}, {"ok", 2.8093e-3 / 3.0, {std::nullopt, 1.0 / 3.0}}};
    designs[1] = {{-0.0, 5e3}, {"error: supports[0].position: must lie in (0, 1], x/l", std::nullopt, {std::nullopt, std::nullopt}}};
    designs[2] = {{1.0, 1e4}, {"timeout: more than 60 s of wall time (raise --point-timeout)", std::nullopt, {std::nullopt, std::nullopt}}};
    {
        DesignJournal j(dir_ + "/out", false, identity_, p_);
        EXPECT_EQ(j.path(), path());
        for (const ComputedDesign& d : designs) j.append(d);
        EXPECT_EQ(j.size(), 3u);
    }
    const DesignJournal back(dir_ + "/out", true, identity_, p_);
    ASSERT_EQ(back.designs().size(), designs.size());
    for (std::size_t i = 0; i < designs.size(); ++i) {
        const ComputedDesign& a = designs[i];
        const ComputedDesign& b = back.designs()[i];
        ASSERT_EQ(b.x.size(), 2u);
        for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(bits(a.x[k]), bits(b.x[k])) << i;
        EXPECT_EQ(a.outcome.status, b.outcome.status) << i;
        ASSERT_EQ(a.outcome.objective.has_value(), b.outcome.objective.has_value()) << i;
        if (a.outcome.objective) {
            EXPECT_EQ(bits(*a.outcome.objective), bits(*b.outcome.objective)) << i;
        }
        EXPECT_EQ(a.outcome.constraints, b.outcome.constraints) << i;
    }
}

TEST_F(OptimizeJournal, WithoutResumeOrOfAnotherProblemItIsRefused) {
    { DesignJournal j(dir_ + "/out", false, identity_, p_); }
    try {
        DesignJournal again(dir_ + "/out", false, identity_, p_);
        ADD_FAILURE() << "a journal was overwritten";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("pass --resume"), std::string::npos) << e.what();
    }
    DesignProblem other = p_;
    other.variables[1] = parse_design_variable("supports[0].stiffness=100:20000", other.base);
    for (const std::string& id : {design_identity_text("case text", other), design_identity_text("other case", p_)}) {
        try {
            DesignJournal j(dir_ + "/out", true, id, other);
            ADD_FAILURE() << "another problem's journal was taken";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(path() + ": belongs to another optimisation"), std::string::npos) << e.what();
        }
    }
}

// A killed process may leave half a line: it is dropped and the next design goes on a line of its
// own. A damaged complete line is an error naming the line.
TEST_F(OptimizeJournal, ATornLastLineIsDroppedADamagedLineRefused) {
    const ComputedDesign d{{0.5, 300.0}, {"ok", 1e-3, {2e-5, 5e-6}}};
    {
        DesignJournal j(dir_ + "/out", false, identity_, p_);
        j.append(d);
    }
    const std::string whole = test::read_text(path());
    test::write_text(path(), whole + "3fe0000000000000:40");
    {
        DesignJournal j(dir_ + "/out", true, identity_, p_);
        EXPECT_EQ(j.designs().size(), 1u);
        j.append(ComputedDesign{{0.25, 300.0}, d.outcome});
    }
    {
        // (Closed before the next is opened: a journal's folder is locked while it is open.)
        const DesignJournal j(dir_ + "/out", true, identity_, p_);
        ASSERT_EQ(j.designs().size(), 2u);
        EXPECT_EQ(j.designs()[1].x[0], 0.25);
    }
    test::write_text(path(), whole + "3fe0000000000000,1e-3,,,ok\n");
    try {
        DesignJournal bad(dir_ + "/out", true, identity_, p_);
        ADD_FAILURE() << "a damaged line was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path() + ":5: not a journal line"), std::string::npos) << e.what();
    }
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

json without_run(json j) {
    j.erase("run");
    return j;
}

// Through the command: SIGINT once a few designs are in the journal ends the search with 130 and
// says how to go on; the journal then holds whole lines; without --resume, or with another bound,
// it is refused (exit 2); --resume ends with the files of an uninterrupted run. The designs are
// slow on purpose: the paper's beam at m = 10, undamped, bounces for its whole 3 ms horizon
// (0.1-0.25 s a design in Release).
TEST(OptimizeStop, SigintKeepsTheJournalAndResumeEndsAsAnUninterruptedRun) {
    const std::string dir = test::make_temp_dir();
    std::string text = test::read_text(test::source_path("examples/paper/free_impact_tip.toml"));
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"elements = 50", "elements = 10"},
                                   {"horizon = \"150 us\"", "horizon = \"3 ms\""},
                                   {"ratios = [0.005, 0.005]", "ratios = [0.0, 0.0]"},
                                   {"damping_ratio = 0.2", "damping_ratio = 0.0"}}) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    }
    const std::string file = dir + "/undamped.toml";
    test::write_text(file, text);
    const auto args = [&](const std::string& out, const std::vector<std::string>& more) {
        std::vector<std::string> a{"optimize", file, "--vary", "supports[0].position=0.6:1", "--minimize", "z_max",
                                   "--max-evals", "12", "--point-timeout", "0", "--out", out};
        a.insert(a.end(), more.begin(), more.end());
        return a;
    };
    const test::CommandResult ref = test::run_vibroimpact(args(dir + "/reference", {"--threads", "2"}));
    ASSERT_EQ(ref.exit_code, 0) << ref.err;
    std::printf("uninterrupted: %.2f s\n", ref.seconds);

    const std::string out = dir + "/out";
    const std::string journal = out + "/optimize.journal";
    std::vector<std::string> argv{test::vibroimpact_path()};
    for (const std::string& a : args(out, {"--threads", "1"})) argv.push_back(a);
    test::ChildProcess child(argv);
    const bool some = test::wait_until([&] { return lines_of(test::read_text(journal)).size() >= 3 + 3; },
                                       test::kHangLimitSeconds);
    ASSERT_TRUE(some) << "no designs reached the journal";
    ASSERT_TRUE(child.running()) << "the search ended before the signal: its designs are no longer slow";
    child.signal(SIGINT);
    const test::CommandResult stopped = child.wait();
    std::printf("stopped %.3f s after SIGINT\n", stopped.after_signal);
    EXPECT_LT(stopped.after_signal, test::kStopBound);
    EXPECT_EQ(stopped.exit_code, 130) << stopped.err;
    const std::string journal_text = test::read_text(journal);
    ASSERT_FALSE(journal_text.empty());
    EXPECT_EQ(journal_text.back(), '\n');
    const std::size_t designs = lines_of(journal_text).size() - 3;
    EXPECT_GE(designs, 3u);
    EXPECT_NE(stopped.err.find("optimize interrupted: " + std::to_string(designs) + " designs computed, kept in " +
                               journal + "; run the same command with --resume to go on"),
              std::string::npos)
        << stopped.err;
    EXPECT_FALSE(fs::exists(out + "/evaluations.csv"));

    const test::CommandResult again = test::run_vibroimpact(args(out, {}));
    EXPECT_EQ(again.exit_code, 2) << again.err;
    EXPECT_NE(again.err.find("pass --resume"), std::string::npos) << again.err;
    std::vector<std::string> other = args(out, {"--resume"});
    other[3] = "supports[0].position=0.6:0.99";
    const test::CommandResult another = test::run_vibroimpact(other);
    EXPECT_EQ(another.exit_code, 2) << another.err;
    EXPECT_NE(another.err.find("belongs to another optimisation"), std::string::npos) << another.err;

    const test::CommandResult resumed = test::run_vibroimpact(args(out, {"--resume", "--threads", "2"}));
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_EQ(test::read_text(out + "/evaluations.csv"), test::read_text(dir + "/reference/evaluations.csv"));
    const json a = json::parse(test::read_text(out + "/optimize.json"));
    const json b = json::parse(test::read_text(dir + "/reference/optimize.json"));
    EXPECT_EQ(without_run(a), without_run(b));
    EXPECT_EQ(a["run"]["from_journal"].get<std::size_t>(), designs) << "one thread computes no design ahead";
    EXPECT_FALSE(fs::exists(journal));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
