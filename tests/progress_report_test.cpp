// The progress of the long commands on stderr: lines on a pipe (done of total, rate, time left),
// a bar redrawn in place on a terminal, nothing with --progress none. The tests set the line
// interval to 0 (a line at every step) or beyond any run, so that what they read never depends on
// how fast the machine is.

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "io/number_text.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

std::string free_impact() { return test::source_path("examples/paper/free_impact_tip.toml"); }

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = text.find('\n', at);
        out.push_back(text.substr(at, end - at));
        at = end == std::string::npos ? text.size() : end + 1;
    }
    return out;
}

// Every line of `err` is a progress line of `what` counting `unit` of `total`; the counts never go
// back and the last is `last_count` (the total unless given). Returns how many lines there were.
std::size_t expect_progress_lines(const std::string& err, const std::string& what, const std::string& unit, std::size_t total,
                                  bool at_most, std::size_t last_count = 0) {
    const std::regex line("^" + what + ": ([0-9]+)/" + std::to_string(total) + " " + unit + ", (- |[0-9.e+]+ )" + unit +
                          "/s, left " + (at_most ? "(at most )?" : "") + "(-|[0-9]+:[0-9][0-9]), elapsed [0-9]+:[0-9][0-9](; .*)?$");
    const std::vector<std::string> lines = lines_of(err);
    if (last_count == 0) last_count = total;
    std::size_t last = 0;
    for (const std::string& l : lines) {
        std::smatch m;
        EXPECT_TRUE(std::regex_match(l, m, line)) << "not a progress line: '" << l << "'";
        if (m.empty()) continue;
        const std::size_t done = std::stoul(m[1].str());
        EXPECT_GE(done, last) << l;
        last = done;
    }
    EXPECT_EQ(last, last_count) << err;
    return lines.size();
}

// The lines of `err` that start with `prefix`, each ended by a newline; with `counts`, only those
// where a count follows the prefix (not a command's event lines, "paper: [ 0.3 s] ...").
std::string lines_starting(const std::string& err, const std::string& prefix, bool counts = false) {
    std::string out;
    for (const std::string& l : lines_of(err)) {
        const bool digit = l.size() > prefix.size() && l[prefix.size()] >= '0' && l[prefix.size()] <= '9';
        if (l.rfind(prefix, 0) == 0 && (!counts || digit)) out += l + "\n";
    }
    return out;
}

// The total of the first count line "what: done/TOTAL unit, ...", or 0.
std::size_t total_of(const std::string& lines) {
    const std::size_t slash = lines.find('/');
    return slash == std::string::npos ? 0 : std::stoul(lines.substr(slash + 1));
}

TEST(ProgressReport, APipedSweepWritesALinePerPointAtIntervalZero) {
    const std::string dir = test::make_temp_dir();
    const auto r = test::run_vibroimpact({"sweep", free_impact(), "--set", "supports[0].position=0.5:1:5", "--threads", "2",
                                          "--progress", "lines", "--progress-interval", "0", "--out", dir + "/s"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(expect_progress_lines(r.err, "sweep", "points", 5, false), 5u) << r.err;
    // auto on a pipe is lines; VIBROIMPACT_PROGRESS gives the default, --progress wins over it.
    const std::vector<std::string> sweep{test::vibroimpact_path(), "sweep", free_impact(), "--set", "supports[0].position=0.5,1",
                                         "--threads", "1", "--progress-interval", "0"};
    const auto automatic = test::run_program(sweep, {"VIBROIMPACT_PROGRESS=auto"});
    EXPECT_EQ(automatic.exit_code, 0) << automatic.err;
    EXPECT_EQ(expect_progress_lines(automatic.err, "sweep", "points", 2, false), 2u);
    std::vector<std::string> lines = sweep;
    lines.insert(lines.end(), {"--progress", "lines"});
    const auto given = test::run_program(lines, {"VIBROIMPACT_PROGRESS=none"});
    EXPECT_EQ(expect_progress_lines(given.err, "sweep", "points", 2, false), 2u);
    std::vector<std::string> none = sweep;
    none.insert(none.end(), {"--progress", "none"});
    EXPECT_EQ(test::run_program(none, {"VIBROIMPACT_PROGRESS=lines"}).err, "");
    fs::remove_all(dir);
}

TEST(ProgressReport, ARunShorterThanTheIntervalWritesNoLine) {
    const auto r = test::run_vibroimpact({"sweep", free_impact(), "--set", "supports[0].position=0.5,1", "--threads", "1",
                                          "--progress", "lines", "--progress-interval", "1e6"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

TEST(ProgressReport, ABadModeIsRefusedBeforeAnyWork) {
    const std::string dir = test::make_temp_dir();
    const std::vector<std::string> sweep{test::vibroimpact_path(), "sweep", free_impact(), "--set", "supports[0].position=0.5,1",
                                         "--out", dir + "/s"};
    const auto env = test::run_program(sweep, {"VIBROIMPACT_PROGRESS=verbose"});
    EXPECT_EQ(env.exit_code, 2);
    EXPECT_EQ(env.err, "vibroimpact: error: VIBROIMPACT_PROGRESS=verbose: must be auto, bar, lines or none\n");
    std::vector<std::string> option = sweep;
    option.insert(option.end(), {"--progress", "verbose"});
    const auto opt = test::run_program(option);
    EXPECT_EQ(opt.exit_code, 2);
    EXPECT_NE(opt.err.find("--progress"), std::string::npos) << opt.err;
    EXPECT_FALSE(fs::exists(dir + "/s"));
    fs::remove_all(dir);
}

// A trajectory of the example with a stiffer stop than the case's: the fit has iterations to make.
std::string fit_data(const std::string& dir) {
    Case c = read_case_file(free_impact());
    c.solver.horizon = 10e-6;
    c.solver.output_step = 100e-9;
    c.supports[0].stiffness *= 1.3;
    SimulationOptions o;
    o.energy = false;
    const SimulationRun run = run_simulation(c, o);
    std::string text = "t_s,tip_m\n";
    for (std::size_t k = 0; k < run.result.history.t.size(); ++k) {
        text += round_trip_text(run.result.history.t[k]) + "," + round_trip_text(run.result.history.watched_v[k]) + "\n";
    }
    test::write_text(dir + "/tip.csv", text);
    return dir + "/tip.csv";
}

TEST(ProgressReport, APipedFitWritesItsIterationsOfTheBudget) {
    const std::string dir = test::make_temp_dir();
    const auto r = test::run_vibroimpact({"fit", free_impact(), "--data", fit_data(dir), "--fit", "supports[0].stiffness=300:3000",
                                          "--starts", "2", "--max-iterations", "20", "--threads", "2", "--progress", "lines",
                                          "--progress-interval", "0", "--out", dir + "/f"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // Budget 2 starts x 20: a line per iteration and one per start that ends before its share.
    EXPECT_GE(expect_progress_lines(r.err, "fit", "iterations", 40, true), 3u) << r.err;
    EXPECT_NE(r.out.find("converged"), std::string::npos) << r.out;
    fs::remove_all(dir);
}

TEST(ProgressReport, APipedOptimizeWritesEachDesignAndTheBestSoFar) {
    const std::string dir = test::make_temp_dir();
    const auto r = test::run_vibroimpact({"optimize", free_impact(), "--vary", "supports[0].position=0.5:1", "--minimize", "z_max",
                                          "--max-evals", "6", "--threads", "2", "--progress", "lines", "--progress-interval", "0",
                                          "--out", dir + "/o"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> lines = lines_of(r.err);
    // One line per design the search used (it may stop short of --max-evals: the time left is "at most").
    ASSERT_GE(lines.size(), 2u) << r.err;
    EXPECT_EQ(lines.front().rfind("optimize: 1/6 designs, ", 0), 0u) << r.err;
    EXPECT_NE(lines.back().find("; best z_max "), std::string::npos) << r.err;
    for (const std::string& l : lines) EXPECT_NE(l.find("left at most"), std::string::npos) << l;
    fs::remove_all(dir);
}

TEST(ProgressReport, APipedAirQWritesEachPressure) {
    const std::string dir = test::make_temp_dir();
    const auto r = test::run_vibroimpact({"air-q", test::source_path("examples/paper/cantilever.toml"), "--progress", "lines",
                                          "--progress-interval", "0", "--out", dir + "/q"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(expect_progress_lines(r.err, "air-q", "pressures", 17, false), 17u) << r.err;
    fs::remove_all(dir);
}

TEST(ProgressReport, APipedPullinWritesItsBranchAndItsTransients) {
    const auto r = test::run_vibroimpact({"pullin", test::source_path("examples/switch/cantilever_switch.toml"), "--dynamic",
                                          "--json", "--progress", "lines", "--progress-interval", "0"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // The branch in step lengths of the air gap (200) and the 16 frequency points.
    const std::string branch = lines_starting(r.err, "pullin: ", true);
    EXPECT_GE(expect_progress_lines(branch, "pullin", "steps", 216, false), 17u) << r.err;
    // One line per transient: the bisection on the reduced model, at most 2 + 11 (0.5 V_PI .. V_PI to
    // 1e-3), and the check of its two ends on the finer model.
    const nlohmann::json dyn = nlohmann::json::parse(r.out)["dynamic"];
    const std::size_t trials = dyn["trials"].size();
    ASSERT_FALSE(dyn["confirmed_on_reduced_modes"].is_null()) << dyn;  // the finer model agreed at once
    const std::string dynamic = lines_starting(r.err, "pullin --dynamic: ");
    EXPECT_EQ(expect_progress_lines(dynamic, "pullin --dynamic", "transients", 15, true, trials), trials) << r.err;
    EXPECT_EQ(lines_of(branch).size() + lines_of(dynamic).size(), lines_of(r.err).size()) << r.err;
}

TEST(ProgressReport, PaperAndValidateCountTheirJobsAndSectionsBesideTheirEventLines) {
    const std::string dir = test::make_temp_dir();
    const auto paper = test::run_vibroimpact({"paper", "--out", dir + "/paper", "--positions", "3", "--modal-positions", "3",
                                              "--prestress-points", "3", "--scan-horizon", "150 us", "--progress", "lines",
                                              "--progress-interval", "0"});
    EXPECT_EQ(paper.exit_code, 0) << paper.err;
    const std::string jobs = lines_starting(paper.err, "paper: ", true);
    const std::size_t total = total_of(jobs);
    EXPECT_GT(total, 10u) << paper.err;
    EXPECT_EQ(expect_progress_lines(jobs, "paper", "jobs", total, false), total);
    EXPECT_NE(paper.err.find("paper: ["), std::string::npos) << paper.err;
    EXPECT_NE(paper.err.find("] figures drawn"), std::string::npos) << paper.err;

    const std::vector<std::string> validate{"validate", "--quick", "--case", free_impact(), "--switch-case",
                                            test::source_path("examples/switch/cantilever_switch.toml"), "--out",
                                            dir + "/v.md"};
    std::vector<std::string> lines = validate;
    lines.insert(lines.end(), {"--progress", "lines", "--progress-interval", "0"});
    const auto v = test::run_vibroimpact(lines);
    EXPECT_EQ(v.exit_code, 0) << v.err;
    EXPECT_EQ(expect_progress_lines(lines_starting(v.err, "validate: ", true), "validate", "sections", 11, false), 11u) << v.err;
    EXPECT_NE(v.err.find("validate: done in "), std::string::npos) << v.err;
    // --progress none is --quiet: nothing on stderr; the two together are refused. Without --out
    // the document goes to stdout.
    std::vector<std::string> none(validate.begin(), validate.end() - 2);
    none.insert(none.end(), {"--progress", "none"});
    const auto quiet = test::run_vibroimpact(none);
    EXPECT_EQ(quiet.err, "");
    EXPECT_EQ(quiet.out.find("# Validation"), 0u);
    std::vector<std::string> both = validate;
    both.insert(both.end(), {"--progress", "lines", "--quiet"});
    const auto refused = test::run_vibroimpact(both);
    EXPECT_EQ(refused.exit_code, 2) << refused.err;
    EXPECT_NE(refused.err.find("excludes"), std::string::npos) << refused.err;
    fs::remove_all(dir);
}

TEST(ProgressReport, OnATerminalAFitDrawsABarAndEndsItsLine) {
    const std::string dir = test::make_temp_dir();
    const auto r = test::run_on_terminal({test::vibroimpact_path(), "fit", free_impact(), "--data", fit_data(dir), "--fit",
                                          "supports[0].stiffness=300:3000", "--max-iterations", "20", "--out", dir + "/f"});
    ASSERT_FALSE(r.hung) << r.out;
    EXPECT_EQ(r.exit_code, 0) << r.out;
    // Redrawn in place ("\r", erase to the end of the line), and the bar's line ended before the
    // results (the terminal turns "\n" into "\r\n").
    EXPECT_NE(r.out.find("\r\033[Kfit ["), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("20/20 iterations"), std::string::npos) << r.out;
    const std::size_t results = r.out.find("Fit of ");
    ASSERT_NE(results, std::string::npos) << r.out;
    EXPECT_EQ(r.out.substr(results - 2, 2), "\r\n") << r.out;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
