// Refusals of the commands' options: one line, exit 2, nothing written (optimize's journal
// included): the same path in two --vary options, options that would do nothing in their
// combination, and values a command derives from an option blamed on that option, not on a line
// of the case file.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

std::string free_impact() { return test::source_path("examples/paper/free_impact_tip.toml"); }
std::string switch_case() { return test::source_path("examples/switch/cantilever_switch.toml"); }

// Runs the command and checks a refusal: exit 2, one line on stderr starting with `message`, and
// `out` (if given) not created.
void expect_refused(const std::vector<std::string>& args, const std::string& message, const std::string& out = "") {
    const auto r = test::run_vibroimpact(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.out << r.err;
    EXPECT_EQ(r.err.rfind("vibroimpact: error: " + message, 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    if (!out.empty()) {
        EXPECT_FALSE(fs::exists(out)) << out;
    }
}

TEST(RefusedCombinations, OptimizeWithOnePathInTwoVaryOptionsWritesNothing) {
    const std::string dir = test::make_temp_dir();
    for (const char* threads : {"1", "2"}) {
        const std::string out = dir + "/out" + threads;
        expect_refused({"optimize", free_impact(), "--vary", "supports[0].position=0.3:1", "--vary", "supports[0].position=0.5:1",
                        "--minimize", "z_max", "--max-evals", "10", "--threads", threads, "--out", out},
                       "--vary supports[0].position=0.5:1: supports[0].position is already varied by --vary "
                       "supports[0].position=0.3:1",
                       out);
    }
    // The next, correct run into that folder goes ahead.
    const auto r = test::run_vibroimpact({"optimize", free_impact(), "--vary", "supports[0].position=0.3:1", "--minimize", "z_max",
                                          "--max-evals", "6", "--threads", "1", "--out", dir + "/out1"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir + "/out1/optimize.json"));
    EXPECT_FALSE(fs::exists(dir + "/out1/optimize.journal"));
    EXPECT_FALSE(fs::exists(dir + "/out1/.vibroimpact.lock"));
    fs::remove_all(dir);
}

TEST(RefusedCombinations, OptimizeRefusedOnAnotherRunsJournalLeavesTheFolderAsItWas) {
    const std::string dir = test::make_temp_dir();
    const std::string out = dir + "/out";
    fs::create_directories(out);
    const std::string journal = "# vibroimpact optimize journal 1\n# problem 0123456789abcdef\nx,z_max,status\n";
    test::write_text(out + "/optimize.journal", journal);
    for (const bool resume : {false, true}) {
        std::vector<std::string> args{"optimize", free_impact(), "--vary", "supports[0].position=0.3:1", "--minimize", "z_max",
                                      "--out", out};
        if (resume) args.push_back("--resume");
        expect_refused(args, out + "/optimize.journal: ");
        EXPECT_EQ(test::read_text(out + "/optimize.journal"), journal);
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
        EXPECT_EQ(names, std::vector<std::string>{"optimize.journal"});
    }
    fs::remove_all(dir);
}

TEST(RefusedCombinations, OptionsThatWouldDoNothingAreRefused) {
    const std::string dir = test::make_temp_dir();
    const std::string out = dir + "/out";
    expect_refused({"optimize", free_impact(), "--vary", "supports[0].position=0.3:1", "--minimize", "z_max", "--max-evals", "10",
                    "--global-evals", "20", "--out", out},
                   "--global-evals 20: must be below --max-evals 10", out);
    expect_refused({"optimize", free_impact(), "--vary", "supports[0].position=0.3:1", "--minimize", "z_max", "--max-evals", "10",
                    "--global-evals", "10", "--out", out},
                   "--global-evals 10: must be below --max-evals 10", out);
    expect_refused({"optimize", free_impact(), "--vary", "supports[0].position=0.3:1", "--minimize", "solver", "--out", out},
                   "--minimize solver: it is text", out);
    for (const std::vector<std::string>& extra : {std::vector<std::string>{"--horizon", "10 us"}, {"--bisections", "5"},
                                                  {"--rel-width", "0.01"}}) {
        std::vector<std::string> args{"pullin", switch_case(), "--out", out};
        args.insert(args.end(), extra.begin(), extra.end());
        expect_refused(args, extra[0] + ": applies to --dynamic", out);
    }
    expect_refused({"sweep", free_impact(), "--set", "supports[0].position=0.5,1", "--modes", "4", "--out", out},
                   "--modes: applies to --analysis modes", out);
    expect_refused({"sweep", free_impact(), "--set", "supports[0].position=0.5,1", "--support-model", "spring", "--out", out},
                   "--support-model: applies to --analysis modes", out);
    expect_refused({"air-q", switch_case(), "--gap", "2 um", "--out", out}, "--gap 2 um: the case's [[electrodes]]", out);
    expect_refused({"air-q", test::source_path("examples/paper/cantilever.toml"), "--gap", "1e-120 m", "--out", out},
                   "--gap 1e-120 m: outside the magnitudes", out);
    fs::remove_all(dir);
}

TEST(RefusedCombinations, ADerivedHorizonIsBlamedOnItsOptionNotOnTheCaseFile) {
    // pullin --dynamic runs its transients over --horizon: a horizon the case's limits refuse is the
    // option's fault; one shorter than the case's output step names both.
    const auto longer = test::run_vibroimpact({"pullin", switch_case(), "--dynamic", "--horizon", "1e6 s"});
    EXPECT_EQ(longer.exit_code, 2) << longer.err;
    EXPECT_EQ(longer.err.rfind("vibroimpact: error: --horizon 1e6 s: 1e+06 s is ", 0), 0u) << longer.err;
    EXPECT_EQ(longer.err.find(".toml:"), std::string::npos) << longer.err;
    // stiction --elements: the element count is the option's.
    expect_refused({"stiction", test::source_path("examples/switch/cantilever_stiction.toml"), "--elements", "5000"},
                   "--elements 5000: must be at most 2000");
    const auto shorter = test::run_vibroimpact({"pullin", switch_case(), "--dynamic", "--horizon", "1 ns"});
    EXPECT_EQ(shorter.exit_code, 2) << shorter.err;
    EXPECT_EQ(shorter.err.rfind("vibroimpact: error: --horizon 1 ns: the case's " + switch_case() + ":", 0), 0u) << shorter.err;
    EXPECT_NE(shorter.err.find("solver.output_step: must not exceed solver.horizon"), std::string::npos) << shorter.err;
}

}  // namespace
}  // namespace vi
