// The fuzz tests' own parts: the checks of one run reject what they must (a fuzz whose check cannot
// fail proves nothing), and the designer's edits make cases the reader accepts, of every kind.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "support/designer_mutator.hpp"
#include "support/fuzz_checks.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

test::FuzzRun a_run() { return {"/tmp/d", "/tmp/d/case.toml", "/tmp/d/no-such-out", "/tmp/d/no-such-out/summary.json", "20 s"}; }

test::CommandResult exit_with(int code, const std::string& err) {
    test::CommandResult r;
    r.exit_code = code;
    r.err = err;
    return r;
}

TEST(FuzzChecks, AnExitTwoMessageMustNameFileLineAndKey) {
    const test::FuzzRun run = a_run();
    EXPECT_TRUE(test::names_file_line_and_key("/tmp/d/case.toml:12: electrodes[0].gap: must be positive", run));
    EXPECT_TRUE(test::names_file_line_and_key("/tmp/d/case.toml:3: TOML syntax: expected '='", run));
    EXPECT_TRUE(test::names_file_line_and_key("/tmp/d/case.toml:9: \"a b\".c: unknown key", run));
    EXPECT_TRUE(test::names_file_line_and_key("/tmp/d/volts.csv:4: expected 2 comma-separated columns", run));
    EXPECT_TRUE(test::names_file_line_and_key(
        "--horizon (default: ten periods of mode 1): the case's /tmp/d/case.toml:64: solver.output_step: too many", run));
    EXPECT_FALSE(test::names_file_line_and_key("/tmp/d/case.toml: cannot read file", run));
    EXPECT_FALSE(test::names_file_line_and_key("/tmp/d/case.toml:12: must be positive", run));
    EXPECT_FALSE(test::names_file_line_and_key("/tmp/d/case.toml:x: beam.length: must be positive", run));
    EXPECT_FALSE(test::names_file_line_and_key("beam.length: must be positive", run));
    EXPECT_FALSE(test::names_file_line_and_key("/elsewhere/case.toml:12: beam.length: must be positive", run));
    EXPECT_FALSE(test::names_file_line_and_key("--horizon: must be positive", run));
}

TEST(FuzzChecks, EachWayARunCanGoWrongIsNamed) {
    const test::FuzzRun run = a_run();
    EXPECT_EQ(test::run_defect(exit_with(2, "vibroimpact: error: /tmp/d/case.toml:2: beam.width: missing required key\n"), run), "");
    EXPECT_EQ(test::run_defect(exit_with(1, "vibroimpact: warning: w\nvibroimpact: failure: the run failed for a reason\n"), run), "");

    test::CommandResult hung = exit_with(137, "");
    hung.hung = true;
    EXPECT_NE(test::run_defect(hung, run).find("killed"), std::string::npos);
    EXPECT_NE(test::run_defect(exit_with(134, "Aborted\n"), run), "");
    EXPECT_NE(test::run_defect(exit_with(1, "vibroimpact: failure: x\nsecond line\n"), run), "");
    EXPECT_NE(test::run_defect(exit_with(1, "vibroimpact pullin: no answer, said in a line of its own\n"), run), "");
    EXPECT_NE(test::run_defect(exit_with(2, "vibroimpact: error: a\nvibroimpact: error: b\n"), run), "");
    EXPECT_NE(test::run_defect(exit_with(2, "vibroimpact: error: something is wrong somewhere\n"), run), "");
    EXPECT_NE(test::run_defect(exit_with(0, ""), run).find("without"), std::string::npos);  // no summary.json
    EXPECT_NE(test::run_defect(exit_with(0, "runtime error: signed integer overflow\n"), run).find("sanitizer"),
              std::string::npos);
}

// Designer mutants of the switch example: most are cases the reader accepts (the edits are meant to
// reach the solvers, not the parser), and over 300 of them every kind of edit occurs.
TEST(DesignerMutator, ItsEditsMakeCasesOfEveryKind) {
    const test::DesignerSource source{test::read_text(test::source_path("examples/switch/cantilever_switch.toml")), 58.4};
    const std::string dir = test::make_temp_dir();
    const std::map<std::string, std::string> kinds = {
        {"second electrode", "a second electrode"}, {"stop removed", "support at line"}, {"to the ends", "runs to"},
        {"gaps crossed", "x the stop's gap"},     {"voltage", "V_PI"},               {"waveform", "waveform of"},
        {"table", "table of"},                    {"sine", "sine at"},               {"air", "[air]"},
        {"dielectric", "dielectric"},             {"adhesion", "adhesion"},          {"mesh", "beam.elements"},
        {"magnitude", "magnitude ->"}};
    std::map<std::string, int> seen;
    int accepted = 0;
    const int count = 300;
    for (int i = 0; i < count; ++i) {
        const test::Mutant m = test::mutate_design(source, 7, static_cast<std::uint64_t>(i));
        ASSERT_FALSE(m.steps.empty()) << i;
        for (const std::string& s : m.steps) {
            for (const auto& [kind, word] : kinds) seen[kind] += s.find(word) != std::string::npos ? 1 : 0;
        }
        test::write_text(dir + "/case.toml", m.text);
        for (const auto& [name, text] : m.files) test::write_text(dir + "/" + name, text);
        try {
            read_case_file(dir + "/case.toml");
            ++accepted;
        } catch (const InputError&) {
        }
    }
    for (const auto& [kind, word] : kinds) EXPECT_GT(seen[kind], 0) << kind;
    EXPECT_GT(accepted, count / 2);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
