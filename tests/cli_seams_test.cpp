// The command line's shared behaviour: simulate --set (the paths and units of sweep --set), "did you
// mean" for a misspelled command or option, --json on the commands with a table or a report, and
// where results go without --out.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using test::run_vibroimpact;

std::string example(const char* path) { return std::string(VI_SOURCE_DIR) + "/" + path; }

const std::string kTip = example("examples/paper/free_impact_tip.toml");
const std::string kCantilever = example("examples/paper/cantilever.toml");

// The command run with `cwd` as its working folder.
test::CommandResult run_in(const std::string& cwd, const std::vector<std::string>& args) {
    std::vector<std::string> argv{"bash", "-c", "cd \"$1\" && shift && exec \"$@\"", "run_in", cwd, test::vibroimpact_path()};
    argv.insert(argv.end(), args.begin(), args.end());
    return test::run_program(argv);
}

nlohmann::json json_of(const test::CommandResult& r) {
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

TEST(SimulateSet, ChangesTheRunAsTheCaseKeyWould) {
    // supports[0].stiffness set on the command line in a unit, and the same value in SI: the same
    // run; a stiffer support than the case's: another run.
    const auto base = json_of(run_vibroimpact({"simulate", kTip, "--json"}));
    const auto set = json_of(run_vibroimpact({"simulate", kTip, "--json", "--set", "supports[0].stiffness=3 kN/m"}));
    const auto si = json_of(run_vibroimpact({"simulate", kTip, "--json", "--set", "supports[0].stiffness=3000"}));
    EXPECT_DOUBLE_EQ(set["resolved"]["supports"][0]["stiffness_n_m"].get<double>(), 3000.0);
    EXPECT_EQ(set["T_s"], si["T_s"]);
    EXPECT_NE(set["T_s"], base["T_s"]);
}

TEST(SimulateSet, RefusesABadPathValueOrUnitNamingTheSetting) {
    const std::string out = test::make_temp_dir() + "/run";
    for (const auto& [setting, says] : std::vector<std::pair<std::string, std::string>>{
             {"supports[0].stifness=1", "did you mean 'stiffness'?"},
             {"supports[0].stiffness=3 V", "supports[0].stiffness"},
             {"supports[0].stiffness", "needs PATH=VALUE"},
             {"supports[3].position=0.5", "supports[3]"},
             {"supports[0].position=1.5", "supports[0].position"}}) {
        const auto r = run_vibroimpact({"simulate", kTip, "--set", setting, "--out", out});
        EXPECT_EQ(r.exit_code, 2) << setting;
        EXPECT_NE(r.err.find("--set"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
        EXPECT_FALSE(fs::exists(out)) << setting;
    }
}

TEST(DidYouMean, NamesTheNearestCommandAndOption) {
    const auto command = run_vibroimpact({"simulat", kTip});
    EXPECT_EQ(command.exit_code, 2);
    EXPECT_NE(command.err.find("did you mean 'simulate'?"), std::string::npos) << command.err;
    const auto option = run_vibroimpact({"simulate", kTip, "--jsn"});
    EXPECT_EQ(option.exit_code, 2);
    EXPECT_NE(option.err.find("did you mean '--json'?"), std::string::npos) << option.err;
    const auto value = run_vibroimpact({"sweep", kTip, "--set=supports[0].position=0.5,0.6", "--threds", "1"});
    EXPECT_EQ(value.exit_code, 2);
    EXPECT_NE(value.err.find("did you mean '--threads'?"), std::string::npos) << value.err;
    // Nothing near: no guess.
    const auto far = run_vibroimpact({"xyzzy"});
    EXPECT_EQ(far.exit_code, 2);
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
    EXPECT_NE(far.err.find("'xyzzy' is not a command"), std::string::npos) << far.err;
}

TEST(JsonEverywhere, SweepPrintsItsSummaryAndTable) {
    const auto j = json_of(run_vibroimpact({"sweep", kTip, "--set", "supports[0].position=0.8,1", "--json", "--threads", "1",
                                            "--progress", "none"}));
    EXPECT_EQ(j["points"], 2);
    ASSERT_EQ(j["table"]["rows"].size(), 2u);
    const auto& cols = j["table"]["columns"];
    const auto at = std::find(cols.begin(), cols.end(), "T_s") - cols.begin();
    ASSERT_LT(static_cast<std::size_t>(at), cols.size());
    EXPECT_TRUE(j["table"]["rows"][0][static_cast<std::size_t>(at)].is_number());
}

TEST(JsonEverywhere, SupportScanAndSwitchReport) {
    const auto scan = json_of(run_vibroimpact({"support-scan", kCantilever, "--positions", "0.5,1", "--json"}));
    EXPECT_EQ(scan["rows"].size(), 2u);
    EXPECT_EQ(scan["columns"][0], "x0_over_l");
    const auto sw = json_of(run_vibroimpact({"switch-report", example("examples/switch/cantilever_switch.toml"), "--json"}));
    EXPECT_TRUE(sw["pullin"].is_object());
    EXPECT_TRUE(sw["transient"]["switching"].is_object());
}

TEST(JsonEverywhere, PaperPrintsItsClaims) {
    const auto j = json_of(run_vibroimpact({"paper", "--json", "--positions", "4", "--modal-positions", "4",
                                            "--prestress-points", "2", "--scan-horizon", "60 us", "--quiet"}));
    ASSERT_TRUE(j["claims"].is_array());
    EXPECT_EQ(j["claims_total"].get<std::size_t>(), j["claims"].size());
    EXPECT_GT(j["claims"].size(), 5u);
    EXPECT_TRUE(j["claims"][0].contains("verdict"));
}

TEST(OutRule, NothingIsWrittenWithoutOut) {
    // Run in a fresh folder: no command may leave an out/ folder (or anything else) there. air-q
    // without --out prints its table (here as JSON) and draws nothing.
    const std::string cwd = test::make_temp_dir();
    const auto air = json_of(run_in(cwd, {"air-q", kCantilever, "--json", "--progress", "none"}));
    EXPECT_GT(air["rows"].size(), 3u);
    EXPECT_EQ(air["columns"][0], "pressure_pa");
    EXPECT_TRUE(fs::is_empty(cwd));
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"paper", "--positions", "4"},
          {"switch-report", example("examples/switch/cantilever_switch.toml")},
          {"optimize", kTip, "--vary", "supports[0].position=0.5:1", "--minimize", "z_max"},
          {"fit", kTip, "--data", kTip, "--fit", "supports[0].stiffness"},
          {"uq", kTip, "--vary", "supports[0].stiffness=normal:1000:10", "--samples", "4"}}) {
        const auto r = run_in(cwd, args);
        EXPECT_EQ(r.exit_code, 2) << args.front() << ": " << r.err;
        EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
    }
    EXPECT_TRUE(fs::is_empty(cwd));
}

}  // namespace
}  // namespace vi
