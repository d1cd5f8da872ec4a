// Work in proportion to the question: runs of the switch examples that a designer's (or a fuzzer's)
// change made run for minutes either answer as quickly as the example does, or are refused before
// any work with one line naming the file, the line and the key, the reason and the limit (exit 2,
// nothing written). Each runs as a user runs it, in a child process; the limit only catches a hang
// (the seconds are printed, never asserted).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CommandResult;

constexpr double kHangSeconds = 120.0;

// The example switch with `from` replaced by `to` (each must occur once), written into dir.
std::string switch_variant(const std::string& dir, const std::string& name,
                           const std::vector<std::pair<std::string, std::string>>& edits) {
    std::string text = test::read_text(test::source_path("examples/switch/cantilever_switch.toml"));
    for (const auto& [from, to] : edits) {
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at == std::string::npos) continue;
        EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from << " occurs twice";
        text.replace(at, from.size(), to);
    }
    const std::string path = dir + "/" + name;
    test::write_text(path, text);
    return path;
}

// Runs the command; prints exit and seconds.
CommandResult run(const std::vector<std::string>& args, const char* what) {
    const CommandResult r = test::run_vibroimpact(args, kHangSeconds);
    std::printf("%s: exit %d in %.2f s\n", what, r.exit_code, r.seconds);
    EXPECT_FALSE(r.hung) << what;
    return r;
}

// `simulate CASE --json`: the summary of an answered run.
json simulate_json(const std::string& path, const char* what) {
    const CommandResult r = run({"simulate", path, "--json"}, what);
    EXPECT_EQ(r.exit_code, 0) << what << ": " << r.err;
    return r.exit_code == 0 ? json::parse(r.out) : json();
}

// A refusal: exit 2, one line "FILE:LINE: KEY: ..." containing every `parts`, nothing written to out.
void expect_refused(const std::vector<std::string>& args, const std::string& file_line_key,
                    const std::vector<std::string>& parts, const std::string& out, const char* what) {
    const CommandResult r = run(args, what);
    EXPECT_EQ(r.exit_code, 2) << what << ": " << r.err;
    const std::string prefix = "vibroimpact: error: " + file_line_key + ": ";
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << what << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << ": " << r.err;
    for (const std::string& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << what << ": " << p << " in " << r.err;
    if (!out.empty()) {
        EXPECT_FALSE(fs::exists(out)) << what;
    }
}

// A voltage table of a million rows held at 70 V gave the step's answer only after every row had
// been an integration stop with a restart (1e4 rows 5.2 s, 1e5 46.6 s): the rows on one straight line
// are no stops now, and the answer is the step's.
TEST(BoundedRuns, AMillionRowVoltageTableAnswersAsTheStepDoes) {
    const std::string dir = test::make_temp_dir();
    std::string rows = "t_s,V_V\n";
    rows.reserve(30'000'000);
    char line[64];
    for (int i = 0; i < 1000000; ++i) {
        std::snprintf(line, sizeof line, "%.12e,70\n", 50e-6 * i / 999999.0);
        rows += line;
    }
    test::write_text(dir + "/volts.csv", rows);
    const std::string table = switch_variant(dir, "table.toml", {{"voltage = \"70 V\"", ""},
                                                                 {"waveform = \"step\"", "waveform = \"table\"\ntable = \"volts.csv\""},
                                                                 {"t_on = \"0 us\"", ""}});
    const json t = simulate_json(table, "1e6-row table");
    const json s = simulate_json(test::source_path("examples/switch/cantilever_switch.toml"), "step");
    ASSERT_TRUE(t.is_object() && s.is_object());
    EXPECT_EQ(t["switching"]["state"], s["switching"]["state"]);
    EXPECT_NEAR(t["switching"]["closing_time_s"].get<double>(), s["switching"]["closing_time_s"].get<double>(), 1e-12);
    EXPECT_EQ(t["switching"]["bounces"], s["switching"]["bounces"]);
}

// A table of noise has a corner at every row, each a stop the integrator cannot do without: past
// kMaxTimeCorners (5000) within the horizon it is refused, naming the table's key.
TEST(BoundedRuns, ANoisyVoltageTableBeyondTheCornerLimitIsRefused) {
    const std::string dir = test::make_temp_dir();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    std::string rows = "t_s,V_V\n";
    char line[64];
    for (int i = 0; i < 10000; ++i) {
        std::snprintf(line, sizeof line, "%.12e,%.6f\n", 50e-6 * i / 9999.0, 70.0 + u(rng));
        rows += line;
    }
    test::write_text(dir + "/noise.csv", rows);
    const std::string path = switch_variant(dir, "noise.toml", {{"voltage = \"70 V\"", ""},
                                                                {"waveform = \"step\"", "waveform = \"table\"\ntable = \"noise.csv\""},
                                                                {"t_on = \"0 us\"", ""}});
    const std::string out = dir + "/out";
    expect_refused({"simulate", path, "--out", out}, path + ":47: electrodes[0].table",
                   {"9998 corners within solver.horizon", "at most 5000", "thin or smooth the table"}, out, "noise table");
}

}  // namespace
}  // namespace vi
