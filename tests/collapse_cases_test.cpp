// Switches driven onto their electrode (docs/electrostatics.md §2, §6): the defect reports whose runs
// never ended (tests/cases/, copied from shared/cases/ with the header that says what they showed),
// run as a user runs them in a child process with a limit of 5 s (more under the sanitizers), and the
// cantilever switch example stepped from 80 to 120 V, each run saying whether it stays closed on its
// stop or collapses onto the electrode, and when.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

using nlohmann::json;
using test::CommandResult;

#if VI_SANITIZE_BUILD
constexpr double kLimitSeconds = 120.0;
#else
constexpr double kLimitSeconds = 5.0;
#endif

// Runs `vibroimpact ARGS --json` within kLimitSeconds; the JSON, or a test failure.
json run_json(std::vector<std::string> args, const char* what) {
    args.push_back("--json");
    const CommandResult r = test::run_vibroimpact(args, kLimitSeconds);
    std::printf("%s: exit %d in %.2f s\n", what, r.exit_code, r.seconds);
    EXPECT_FALSE(r.hung) << what << ": no end within " << kLimitSeconds << " s";
    EXPECT_EQ(r.exit_code, 0) << what << ": " << r.err;
    if (r.exit_code != 0) return json();
    return json::parse(r.out);
}

// The cantilever switch stepped to 90 V (1.54 V_PI) never ended: the closed beam collapses onto its
// electrode at about 3.27 us (an independent reduced-order model: 0.99 of the gap at 3.27 us).
TEST(CollapseCases, OverdrivenSwitchCollapsesOntoItsElectrode) {
    const json s = run_json({"simulate", test::source_path("tests/cases/overdrive_collapse.toml")}, "overdrive_collapse");
    ASSERT_TRUE(s.is_object());
    const json& w = s["switching"];
    EXPECT_EQ(w["state"], "collapsed") << w;
    EXPECT_EQ(s["Tp_reason"], "collapsed");
    ASSERT_TRUE(w["collapse"].is_object()) << w;
    const json& c = w["collapse"];
    EXPECT_EQ(c["electrode"], "electrodes[0]");
    EXPECT_NEAR(c["time_s"].get<double>(), 3.27e-6, 0.02e-6);
    EXPECT_EQ(c["voltage_v"].get<double>(), 90.0);
    EXPECT_NEAR(c["air_gap_m"].get<double>(), 0.01 * 2e-6, 1e-12);
    // Under the electrode's span (x/l 0.1 .. 0.9), past the middle: the tip is held by the stop.
    EXPECT_GT(c["x_over_l"].get<double>(), 0.5);
    EXPECT_LT(c["x_over_l"].get<double>(), 0.9);
    // The ledger up to the collapse: the first contact on the stop, still closed when it came.
    ASSERT_EQ(w["contacts"].size(), 1u);
    EXPECT_NEAR(w["closing_time_s"].get<double>(), 2.294e-6, 0.001e-6);
    EXPECT_TRUE(w["contacts"][0]["closed_at_end"].get<bool>());
    std::printf("overdrive_collapse: collapse at %.5g us, x/l = %.4g\n", c["time_s"].get<double>() * 1e6,
                c["x_over_l"].get<double>());
}

// The bridge with its electrode running to the clamped end: the beam collapses onto the electrode.
TEST(CollapseCases, BridgeWithItsElectrodeToTheAnchorCollapses) {
    const json s = run_json({"simulate", test::source_path("tests/cases/bridge_electrode_to_anchor.toml")},
                            "bridge_electrode_to_anchor");
    ASSERT_TRUE(s.is_object());
    const json& w = s["switching"];
    EXPECT_EQ(w["state"], "collapsed") << w;
    ASSERT_TRUE(w["collapse"].is_object());
    const double x = w["collapse"]["x_over_l"].get<double>();
    EXPECT_GT(x, 0.5);  // on the side of the longer electrode
    EXPECT_LE(x, 1.0);
    std::printf("bridge_electrode_to_anchor: collapse at %.5g us, x/l = %.4g\n",
                w["collapse"]["time_s"].get<double>() * 1e6, x);
}

// `pullin --dynamic` of a cantilever under a full-length electrode without a support never answered:
// the beam's own collapse decides each trial. For this beam about 0.909 of the static 47.30 V.
TEST(CollapseCases, DynamicPullinWithoutAStopAnswers) {
    const json j = run_json({"pullin", test::source_path("tests/cases/dynamic_pullin_without_stop.toml"), "--dynamic"},
                            "dynamic_pullin_without_stop");
    ASSERT_TRUE(j.is_object());
    const json& d = j["dynamic"];
    EXPECT_NEAR(d["static_voltage_V"].get<double>(), 47.30, 0.01);
    EXPECT_NEAR(d["ratio_to_static"].get<double>(), 0.909, 0.002);
    EXPECT_LE(d["lower_V"].get<double>(), d["voltage_V"].get<double>());
    EXPECT_GE(d["upper_V"].get<double>(), d["voltage_V"].get<double>());
    bool collapsed = false;
    for (const json& t : d["trials"]) collapsed = collapsed || t["how"] == "collapse";
    EXPECT_TRUE(collapsed) << "the beam's collapse did not decide any trial";
    std::printf("dynamic_pullin_without_stop: V_DPI = %.6g V (%.4f of static), %s\n", d["voltage_V"].get<double>(),
                d["ratio_to_static"].get<double>(), d["model"].get<std::string>().c_str());
}

}  // namespace
}  // namespace vi
