// `vibroimpact switch-report`: the page, its figures and data files agree with what `pullin` and
// `simulate` give for the same case, a negative drive is drawn, and a case without an electrode is refused.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

TEST(SwitchReport, ThePageHoldsThePullinAndTheBounceLedgerOfTheExample) {
    const std::string file = test::source_path("examples/switch/cantilever_switch.toml");
    const std::string tmp = test::make_temp_dir();
    const std::string dir = tmp + "/report";
    const auto r = test::run_vibroimpact({"switch-report", file, "--out", dir});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* name : {"report.html", "report.md", "pullin.json", "pullin_branch.csv", "summary.json", "history.csv",
                             "switch_pullin.png", "switch_cv.svg", "switch_fv.gp", "switch_transient.csv"}) {
        EXPECT_TRUE(fs::exists(dir + "/" + name)) << name;
    }
    // The same numbers as the separate commands give.
    const auto p = test::run_vibroimpact({"pullin", file, "--json"});
    ASSERT_EQ(p.exit_code, 0) << p.err;
    const json alone = json::parse(p.out);
    const json page = json::parse(test::read_text(dir + "/pullin.json"));
    EXPECT_EQ(page["pullin"]["voltage_V"].get<double>(), alone["pullin"]["voltage_V"].get<double>());
    const json summary = json::parse(test::read_text(dir + "/summary.json"));
    const std::size_t episodes = summary["episodes"].size();
    ASSERT_GT(episodes, 1u);  // it bounces
    // One ledger row per episode in the Markdown page: "| k | supports[0] | ..."
    const std::string md = test::read_text(dir + "/report.md");
    std::size_t rows = 0;
    for (std::size_t at = md.find("| supports[0] |"); at != std::string::npos; at = md.find("| supports[0] |", at + 1)) ++rows;
    EXPECT_EQ(rows, episodes);
    char v_pi[32];
    std::snprintf(v_pi, sizeof v_pi, "%.5g", alone["pullin"]["voltage_V"].get<double>());
    EXPECT_NE(md.find(v_pi), std::string::npos) << v_pi;
    EXPECT_NE(md.find("### Switching ledger"), std::string::npos);
    EXPECT_NE(test::read_text(dir + "/report.html").find("data:image/png;base64,"), std::string::npos);
    fs::remove_all(tmp);
}

TEST(SwitchReport, ACaseWithoutAnElectrodeIsRefused) {
    const std::string tmp = test::make_temp_dir();
    const auto r = test::run_vibroimpact(
        {"switch-report", test::source_path("examples/paper/free_impact_tip.toml"), "--out", tmp + "/report"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("electrodes"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp + "/report"));
    fs::remove_all(tmp);
}

// A negative drive pulls as a positive one does (the force goes with V^2): the report of the example
// at -70 V is drawn, its voltage axis below zero, and the voltage column holds -70 V.
TEST(SwitchReport, ANegativeVoltageIsDrawnOnItsOwnSideOfZero) {
    std::string text = test::read_text(test::source_path("examples/switch/cantilever_switch.toml"));
    const std::string volts = "voltage = \"70 V\"";
    ASSERT_NE(text.find(volts), std::string::npos);
    text.replace(text.find(volts), volts.size(), "voltage = \"-70 V\"");
    const std::string tmp = test::make_temp_dir();
    test::write_text(tmp + "/case.toml", text);
    const auto r = test::run_vibroimpact({"switch-report", tmp + "/case.toml", "--out", tmp + "/report"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(test::read_text(tmp + "/report/switch_transient.gp").find("set y2range [*:0]"), std::string::npos);
    EXPECT_NE(test::read_text(tmp + "/report/switch_transient.csv").find(",-70\n"), std::string::npos);
    EXPECT_TRUE(fs::exists(tmp + "/report/switch_transient.png"));
    fs::remove_all(tmp);
}

}  // namespace
}  // namespace vi
