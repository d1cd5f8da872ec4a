// Switches driven onto their electrode (docs/electrostatics.md §2, §6): the defect reports whose runs
// never ended (tests/cases/, copied from shared/cases/ with the header that says what they showed),
// run as a user runs them in a child process, and the cantilever switch example stepped from 80 to
// 120 V, each run saying whether it stays closed on its stop or collapses onto the electrode, and
// when, against an independent reduced-order model (validation/switch_collapse_reference.hpp;
// docs/validation.md §11). Each run takes a fraction of a second to a few seconds (printed); the
// child's limit only catches a hang, the tests assert the answers.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "validation/report.hpp"
#include "validation/switch_collapse_reference.hpp"

namespace vi {
namespace {

using nlohmann::json;
using test::CommandResult;

constexpr double kLimitSeconds = 300.0;

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

// `simulate` of the example switch stepped to `volts` (its 70 V line replaced), as JSON.
json stepped_switch(double volts, const std::string& dir) {
    std::string text = test::read_text(test::source_path("examples/switch/cantilever_switch.toml"));
    const std::string from = "voltage = \"70 V\"";
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos);
    if (at == std::string::npos) return json();
    char v[64];
    std::snprintf(v, sizeof v, "voltage = \"%.6g V\"", volts);
    text.replace(at, from.size(), v);
    const std::string path = dir + "/switch.toml";
    test::write_text(path, text);
    return run_json({"simulate", path}, v);
}

CantileverSwitchSpec example_switch_spec() {
    return validation_detail::switch_spec(read_case_file(test::source_path("examples/switch/cantilever_switch.toml")));
}

// The example switch stepped to 80 .. 120 V: at 80 and 85 V it closes and stays closed on its stop
// for the 50 us; from 90 V the closed beam snaps through onto the electrode. Closing and collapse
// times, and where the gap closes, as the independent model has them (they agree to 2e-5 and 4e-4
// relative, docs/validation.md §11).
TEST(CollapseCases, ExampleSwitchSteppedFrom80To120VSaysClosedOrCollapsedAndWhen) {
    const CantileverSwitchSpec spec = example_switch_spec();
    const std::string dir = test::make_temp_dir();
    for (const double v : {80.0, 85.0, 90.0, 95.0, 100.0, 120.0}) {
        const json s = stepped_switch(v, dir);
        ASSERT_TRUE(s.is_object()) << v;
        const SwitchRomRun rom = cantilever_switch_rom(spec, v);
        const json& w = s["switching"];
        const bool collapses = v >= 90.0;
        EXPECT_EQ(rom.collapsed, collapses) << v << " V";
        EXPECT_EQ(w["state"], collapses ? "collapsed" : "closed") << v << " V: " << w;
        EXPECT_NEAR(w["closing_time_s"].get<double>(), rom.closing_time, 1e-4 * rom.closing_time) << v << " V";
        if (collapses) {
            ASSERT_TRUE(w["collapse"].is_object()) << w;
            EXPECT_NEAR(w["collapse"]["time_s"].get<double>(), rom.collapse_time, 2e-3 * rom.collapse_time) << v << " V";
            EXPECT_NEAR(w["collapse"]["x_over_l"].get<double>(), rom.collapse_x, 0.02) << v << " V";
            EXPECT_EQ(w["collapse"]["voltage_v"].get<double>(), v);
            std::printf("%g V: closes at %.5g us, collapses at %.5g us (reduced-order model %.5g us), x/l %.3f\n", v,
                        w["closing_time_s"].get<double>() * 1e6, w["collapse"]["time_s"].get<double>() * 1e6,
                        rom.collapse_time * 1e6, w["collapse"]["x_over_l"].get<double>());
        } else {
            EXPECT_TRUE(w["stable_contact_s"].is_number()) << w;
            std::printf("%g V: closes at %.5g us, stays closed from %.5g us\n", v, w["closing_time_s"].get<double>() * 1e6,
                        w["stable_contact_s"].get<double>() * 1e6);
        }
    }
}

// The threshold between the two: the independent model bisected to 0.02 V; the FE model stays
// closed 0.05 V below that bracket and collapses 0.05 V above it (both thresholds: docs/validation.md
// §11).
TEST(CollapseCases, ExampleSwitchCollapseThresholdAgreesWithAnIndependentModel) {
    const VoltageBracket b = cantilever_switch_rom_threshold(example_switch_spec(), 85.0, 90.0, 0.02);
    std::printf("reduced-order model: stays closed at %.3f V, collapses at %.3f V\n", b.stays, b.collapses);
    const std::string dir = test::make_temp_dir();
    const json below = stepped_switch(b.stays - 0.05, dir);
    ASSERT_TRUE(below.is_object());
    EXPECT_EQ(below["switching"]["state"], "closed") << below["switching"];
    const json above = stepped_switch(b.collapses + 0.05, dir);
    ASSERT_TRUE(above.is_object());
    EXPECT_EQ(above["switching"]["state"], "collapsed") << above["switching"];
}

}  // namespace
}  // namespace vi
