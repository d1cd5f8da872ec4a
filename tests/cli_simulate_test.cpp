// The `simulate` command end to end: the summary JSON schema and its internal consistency, the files
// written by --out, and the handling of bad input (one line on stderr, exit code 2, nothing written).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "support/text_checks.hpp"

namespace vi {
namespace {

using test::read_text;
namespace fs = std::filesystem;
using nlohmann::json;
using test::run_vibroimpact;

const std::string kExample = "examples/paper/free_impact_tip.toml";

std::vector<std::string> read_lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
    return text;
}

// |a - b| <= rel * max(|a|, |b|)
void expect_rel(double a, double b, double rel, const std::string& what) {
    EXPECT_LE(std::abs(a - b), rel * std::max(std::abs(a), std::abs(b))) << what << ": " << a << " vs " << b;
}

// The example's --json output, computed once for the whole suite.
class CliSimulate : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        result_ = new test::CommandResult(run_vibroimpact({"simulate", test::source_path(kExample), "--json"}));
    }
    static void TearDownTestSuite() {
        delete result_;
        result_ = nullptr;
    }
    static const test::CommandResult& result() { return *result_; }
    static json summary() { return json::parse(result_->out); }

private:
    static test::CommandResult* result_;
};

test::CommandResult* CliSimulate::result_ = nullptr;

void expect_contact_row(const json& row, const std::string& what) {
    ASSERT_TRUE(row.is_object()) << what;
    EXPECT_TRUE(row["support"].is_number_integer()) << what;
    for (const char* key : {"t_on_s", "t_off_s", "v_in_m_s", "v_out_m_s", "peak_force_n", "peak_penetration_m"}) {
        EXPECT_TRUE(row.contains(key)) << what << ": " << key;
        EXPECT_TRUE(row[key].is_number()) << what << ": " << key;
    }
}

TEST_F(CliSimulate, JsonHasEveryKeyWithItsType) {
    ASSERT_EQ(result().exit_code, 0) << result().err;
    EXPECT_TRUE(result().err.empty()) << result().err;
    const json j = summary();
    ASSERT_TRUE(j.is_object());

    EXPECT_TRUE(j["omega1_rad_s"].is_number());
    ASSERT_TRUE(j["impacts"].is_array());
    ASSERT_FALSE(j["impacts"].empty());
    for (std::size_t i = 0; i < j["impacts"].size(); ++i) {
        const json& im = j["impacts"][i];
        expect_contact_row(im, "impacts[" + std::to_string(i) + "]");
        EXPECT_TRUE(im["episodes"].is_number_integer()) << i;
    }
    ASSERT_TRUE(j["episodes"].is_array());
    ASSERT_FALSE(j["episodes"].empty());
    for (std::size_t i = 0; i < j["episodes"].size(); ++i) {
        expect_contact_row(j["episodes"][i], "episodes[" + std::to_string(i) + "]");
    }
    // Headline times: numbers here (the example sees several cycles and settles within its horizon).
    for (const char* key : {"T_s", "T1_s", "T2_s", "Tp_s", "tau", "tau1", "tau2", "tau_p", "y_max_m", "z_max",
                            "y_max_contact_m", "tip_min_m"}) {
        ASSERT_TRUE(j.contains(key)) << key;
        EXPECT_TRUE(j[key].is_number()) << key << " = " << j[key].dump();
    }
    EXPECT_TRUE(j["Tp_reason"].is_string());
    // Every event search of the default example is proven but for the forced first steps after a
    // contact ends, over which the watched function stays within roundoff of zero.
    ASSERT_TRUE(j["solver"].is_object());
    EXPECT_TRUE(j["solver"]["unproven_steps"].is_number_integer());
    ASSERT_TRUE(j["solver"]["unproven_excess"].is_number());
    EXPECT_LT(j["solver"]["unproven_excess"].get<double>(), 1e-12);
    ASSERT_TRUE(j["energy"].is_object());
    for (const char* when : {"initial", "final"}) {
        ASSERT_TRUE(j["energy"][when].is_object()) << when;
        for (const char* key : {"kinetic_j", "strain_j", "contact_spring_j", "electrical_j", "rayleigh_dissipated_j",
                                "contact_dissipated_j", "external_work_j"}) {
            EXPECT_TRUE(j["energy"][when][key].is_number()) << when << "." << key;
        }
    }
    ASSERT_TRUE(j["cycles"].is_object());
    for (const char* key : {"T_s", "T1_s", "T2_s"}) {
        ASSERT_TRUE(j["cycles"][key].is_array()) << key;
        EXPECT_FALSE(j["cycles"][key].empty()) << key;
        for (const json& v : j["cycles"][key]) EXPECT_TRUE(v.is_number()) << key;
    }

    const json& r = j["resolved"];
    ASSERT_TRUE(r.is_object());
    ASSERT_TRUE(r["supports"].is_array());
    ASSERT_EQ(r["supports"].size(), 1u);
    EXPECT_TRUE(r["supports"][0]["stiffness_n_m"].is_number());
    EXPECT_TRUE(r["supports"][0]["damping_n_s_m"].is_number());
    EXPECT_TRUE(r["damping"]["alpha_1_s"].is_number());
    EXPECT_TRUE(r["damping"]["beta_s"].is_number());
    EXPECT_TRUE(r["initial"]["y0_m"].is_number());
    for (const char* key : {"group_gap_s", "horizon_s", "output_step_s", "settle_tolerance", "min_search_step"}) {
        EXPECT_TRUE(r["solver"][key].is_number()) << "solver." << key;
    }
    EXPECT_TRUE(r["solver"]["method"].is_string());
    EXPECT_TRUE(r["beam"]["length_m"].is_number());
}

TEST_F(CliSimulate, ResolvedParametersAreTheCaseAndItsDocumentedDefaults) {
    ASSERT_EQ(result().exit_code, 0) << result().err;
    const json j = summary();
    const json& r = j["resolved"];
    const double w1 = j["omega1_rad_s"].get<double>();
    EXPECT_GT(w1, 0.0);
    EXPECT_EQ(r["solver"]["method"], "exact");
    expect_rel(r["supports"][0]["stiffness_n_m"].get<double>(), 1000.0, 1e-12, "Kc");
    expect_rel(r["beam"]["length_m"].get<double>(), 117e-6, 1e-12, "l");
    expect_rel(r["initial"]["y0_m"].get<double>(), 1e-6, 1e-12, "y0");
    expect_rel(r["solver"]["horizon_s"].get<double>(), 150e-6, 1e-12, "horizon");
    expect_rel(r["solver"]["output_step_s"].get<double>(), 10e-9, 1e-12, "output_step");
    expect_rel(r["solver"]["settle_tolerance"].get<double>(), 0.01, 1e-12, "settle_tolerance");
    // Default group gap: a quarter of the first natural period of the beam without supports.
    expect_rel(r["solver"]["group_gap_s"].get<double>(), 0.25 * 2.0 * std::numbers::pi / w1, 1e-12, "group_gap");

    // Rayleigh coefficients from ratios [0.005, 0.005] at modes 1 and 2: alpha + beta w1^2 = 2 w1 xi1.
    const double alpha = r["damping"]["alpha_1_s"].get<double>();
    const double beta = r["damping"]["beta_s"].get<double>();
    EXPECT_GT(alpha, 0.0);
    EXPECT_GT(beta, 0.0);
    expect_rel(alpha + beta * w1 * w1, 2.0 * w1 * 0.005, 1e-9, "Rayleigh condition at mode 1");

    // Cc from damping_ratio 0.2 at the free end of a cantilever: 2 zeta sqrt(Kc rho A l / 4).
    const double rho_a_l = 8902.0 * 30e-6 * 2e-6 * 117e-6;
    expect_rel(r["supports"][0]["damping_n_s_m"].get<double>(), 2.0 * 0.2 * std::sqrt(1000.0 * rho_a_l / 4.0), 1e-3,
               "Cc");
}

TEST_F(CliSimulate, SummaryIsConsistent) {
    ASSERT_EQ(result().exit_code, 0) << result().err;
    const json j = summary();
    const double w1 = j["omega1_rad_s"].get<double>();
    const double T = j["T_s"].get<double>();
    const double T1 = j["T1_s"].get<double>();
    const double T2 = j["T2_s"].get<double>();
    const double Tp = j["Tp_s"].get<double>();

    // Dimensionless times.
    expect_rel(j["tau"].get<double>(), w1 * T, 1e-12, "tau");
    expect_rel(j["tau1"].get<double>(), w1 * T1, 1e-12, "tau1");
    expect_rel(j["tau2"].get<double>(), w1 * T2, 1e-12, "tau2");
    expect_rel(j["tau_p"].get<double>(), w1 * Tp, 1e-12, "tau_p");

    // Headline = first cycle, and a cycle is a flight plus an impact.
    const json& cy = j["cycles"];
    expect_rel(T, cy["T_s"][0].get<double>(), 1e-12, "T vs cycles.T_s[0]");
    expect_rel(T1, cy["T1_s"][0].get<double>(), 1e-12, "T1 vs cycles.T1_s[0]");
    expect_rel(T2, cy["T2_s"][0].get<double>(), 1e-12, "T2 vs cycles.T2_s[0]");
    expect_rel(T, cy["T1_s"][0].get<double>() + cy["T2_s"][0].get<double>(), 1e-12, "T = T1 + T2");
    EXPECT_GT(T1, 0.0);
    EXPECT_GT(T2, 0.0);

    // The first cycle spans from the first impact's onset to the second's.
    const json& im = j["impacts"];
    ASSERT_GE(im.size(), 2u);
    expect_rel(T, im[1]["t_on_s"].get<double>() - im[0]["t_on_s"].get<double>(), 1e-12, "T from impacts");
    expect_rel(T2, im[0]["t_off_s"].get<double>() - im[0]["t_on_s"].get<double>(), 1e-12, "T2 from impacts");

    // Impacts in onset order, each of positive duration, grouping every episode once.
    long grouped = 0;
    for (std::size_t i = 0; i < im.size(); ++i) {
        EXPECT_GT(im[i]["t_off_s"].get<double>(), im[i]["t_on_s"].get<double>()) << "impact " << i;
        EXPECT_GE(im[i]["episodes"].get<int>(), 1) << "impact " << i;
        EXPECT_GT(im[i]["peak_force_n"].get<double>(), 0.0) << "impact " << i;
        EXPECT_GT(im[i]["peak_penetration_m"].get<double>(), 0.0) << "impact " << i;
        EXPECT_EQ(im[i]["support"].get<int>(), 0) << "impact " << i;
        if (i > 0) {
            EXPECT_GT(im[i]["t_on_s"].get<double>(), im[i - 1]["t_off_s"].get<double>()) << "impact " << i;
        }
        grouped += im[i]["episodes"].get<int>();
    }
    const json& ep = j["episodes"];
    EXPECT_GE(ep.size(), im.size());
    EXPECT_EQ(grouped, static_cast<long>(ep.size()));
    for (std::size_t i = 0; i < ep.size(); ++i) {
        EXPECT_GE(ep[i]["t_off_s"].get<double>(), ep[i]["t_on_s"].get<double>()) << "episode " << i;
        if (i > 0) {
            EXPECT_GE(ep[i]["t_on_s"].get<double>(), ep[i - 1]["t_off_s"].get<double>()) << "episode " << i;
        }
    }
    // The first impact: falling onto the support below, bouncing back up.
    EXPECT_LT(im[0]["v_in_m_s"].get<double>(), 0.0);
    EXPECT_GT(im[0]["v_out_m_s"].get<double>(), 0.0);
    EXPECT_GT(im[0]["t_on_s"].get<double>(), 0.0);

    // T_p: inside the horizon, at the end of an impact.
    EXPECT_EQ(j["Tp_reason"], "settled");
    EXPECT_GT(Tp, T);
    EXPECT_LT(Tp, j["resolved"]["solver"]["horizon_s"].get<double>());
    bool tp_is_an_impact_end = false;
    for (const json& i : im) tp_is_an_impact_end = tp_is_an_impact_end || i["t_off_s"].get<double>() == Tp;
    EXPECT_TRUE(tp_is_an_impact_end) << Tp;

    // Rebound: positive, below the initial lift (energy is lost), seen at the tip, which is the contact point.
    const double y_max = j["y_max_m"].get<double>();
    const double l = j["resolved"]["beam"]["length_m"].get<double>();
    EXPECT_GT(y_max, 0.0);
    EXPECT_LT(y_max, j["resolved"]["initial"]["y0_m"].get<double>());
    expect_rel(j["z_max"].get<double>(), y_max / l, 1e-12, "z_max = y_max / l");
    expect_rel(j["y_max_contact_m"].get<double>(), y_max, 1e-9, "contact point is the tip");
    EXPECT_LT(j["tip_min_m"].get<double>(), 0.0);

    // Energy: released from rest; what is left plus what was dissipated is what there was.
    const json& e0 = j["energy"]["initial"];
    const json& e1 = j["energy"]["final"];
    EXPECT_GT(e0["strain_j"].get<double>(), 0.0);
    EXPECT_LE(std::abs(e0["kinetic_j"].get<double>()), 1e-12 * e0["strain_j"].get<double>());
    auto stored = [](const json& e) {
        return e["kinetic_j"].get<double>() + e["strain_j"].get<double>() + e["contact_spring_j"].get<double>();
    };
    const double dissipated = e1["rayleigh_dissipated_j"].get<double>() + e1["contact_dissipated_j"].get<double>();
    EXPECT_GT(e1["rayleigh_dissipated_j"].get<double>(), 0.0);
    EXPECT_GT(e1["contact_dissipated_j"].get<double>(), 0.0);
    EXPECT_LT(stored(e1), stored(e0));
    expect_rel(stored(e1) + dissipated, stored(e0) + e1["external_work_j"].get<double>(), 1e-6, "energy balance");
}

TEST_F(CliSimulate, OutFolderHoldsHistoryEventsAndTheSameSummary) {
    ASSERT_EQ(result().exit_code, 0) << result().err;
    const json from_stdout = summary();

    const std::string tmp = test::make_temp_dir();
    const std::string dir = tmp + "/out";
    const auto r = run_vibroimpact({"simulate", test::source_path(kExample), "--out", dir});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* f : {"history.csv", "events.csv", "summary.json"}) {
        EXPECT_TRUE(fs::is_regular_file(dir + "/" + f)) << f;
    }
    // No temporary files left behind.
    std::size_t entries = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        (void)e;
        ++entries;
    }
    EXPECT_EQ(entries, 3u);

    const auto history = read_lines(dir + "/history.csv");
    ASSERT_FALSE(history.empty());
    EXPECT_EQ(history[0].rfind("t_s,tip_m,tip_velocity_m_s,contact0_m", 0), 0u) << history[0];
    // horizon 150 us, output_step 10 ns: floor(150 us / 10 ns) + 1 = 15001 samples, t = 0 ... horizon.
    const double horizon = from_stdout["resolved"]["solver"]["horizon_s"].get<double>();
    const double step = from_stdout["resolved"]["solver"]["output_step_s"].get<double>();
    const auto expected_rows = static_cast<std::size_t>(std::floor(horizon / step * (1.0 + 1e-12))) + 1;
    EXPECT_EQ(expected_rows, 15001u);
    EXPECT_EQ(history.size() - 1, expected_rows);
    if (history.size() > 2) {
        const std::size_t columns = static_cast<std::size_t>(std::count(history[0].begin(), history[0].end(), ',')) + 1;
        EXPECT_EQ(static_cast<std::size_t>(std::count(history[1].begin(), history[1].end(), ',')) + 1, columns);
        EXPECT_EQ(std::stod(history[1].substr(0, history[1].find(','))), 0.0);
        expect_rel(std::stod(history.back().substr(0, history.back().find(','))), horizon, 1e-12, "last sample");
        // Released from rest at the lift y0.
        const std::string first = history[1].substr(history[1].find(',') + 1);
        expect_rel(std::stod(first.substr(0, first.find(','))), 1e-6, 1e-9, "tip at t = 0");
    }

    const auto events = read_lines(dir + "/events.csv");
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events[0].rfind("episode,impact,support,t_on_s,t_off_s", 0), 0u) << events[0];
    EXPECT_EQ(events.size() - 1, from_stdout["episodes"].size());

    const json from_file = json::parse(read_text(dir + "/summary.json"));
    EXPECT_EQ(from_file, from_stdout) << "summary.json differs from --json";
    EXPECT_NE(r.out.find(dir), std::string::npos) << r.out;
    fs::remove_all(tmp);
}

struct BadCase {
    const char* what;
    std::string text;
    const char* key;  // the key the message must name
};

// The watched point is named for what it is: the free end of a cantilever is its tip, a beam held at
// both ends is watched at mid-span (examples/devices/bridge_relay.toml), never called a tip.
TEST(CliSimulateWatchedPoint, CantileverTipAndBridgeMidspanAreNamedSo) {
    const std::string dir = test::make_temp_dir();
    const auto r = test::run_vibroimpact(
        {"simulate", test::source_path("examples/devices/bridge_relay.toml"), "--out", dir + "/bridge"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto history = read_lines(dir + "/bridge/history.csv");
    ASSERT_FALSE(history.empty());
    EXPECT_EQ(history[0].rfind("t_s,midspan_m,midspan_velocity_m_s,", 0), 0u) << history[0];
    EXPECT_EQ(history[0].find("tip"), std::string::npos) << history[0];
    std::ifstream in(dir + "/bridge/summary.json");
    const json summary = json::parse(in);
    EXPECT_EQ(summary["watched_point"]["name"], "midspan");
    EXPECT_DOUBLE_EQ(summary["watched_point"]["x_over_l"].get<double>(), 0.5);
    const auto tip = test::run_vibroimpact({"simulate", test::source_path("examples/paper/free_impact_tip.toml"), "--json"});
    ASSERT_EQ(tip.exit_code, 0) << tip.err;
    const json j = json::parse(tip.out);
    EXPECT_EQ(j["watched_point"]["name"], "tip");
    EXPECT_DOUBLE_EQ(j["watched_point"]["x_over_l"].get<double>(), 1.0);
    fs::remove_all(dir);
}

TEST(CliSimulateBadInput, EveryBadInputGivesOneLineExitTwoAndWritesNothing) {
    const std::string good = read_text(test::source_path(kExample));
    ASSERT_FALSE(good.empty());
    const std::string above_support = "[[supports]]\nposition = 1.0\nside = \"above\"\ngap = \"0 um\"\n"
                                      "stiffness = \"1000 N/m\"\n\n[initial]";
    const std::vector<BadCase> cases = {
        {"negative stiffness", replace(good, "stiffness = \"1000 N/m\"", "stiffness = \"-1000 N/m\""),
         "supports[0].stiffness"},
        {"overlapping supports",
         replace(replace(good, "gap = \"0 um\"", "prestress = \"0.1 um\""), "[initial]", above_support),
         "supports[1].gap"},
        {"initial state penetrates a support",
         replace(good, "[initial]", replace(above_support, "gap = \"0 um\"", "gap = \"0.5 um\"")),
         "initial.displacement"},
        {"horizon too short", replace(good, "horizon = \"150 us\"", "horizon = \"0.5 us\""), "solver.horizon"},
        {"output step above horizon", replace(good, "output_step = \"10 ns\"", "output_step = \"200 us\""),
         "solver.output_step"},
        {"missing horizon", replace(good, "horizon = \"150 us\"", ""), "solver.horizon"},
        {"unknown solver key", replace(good, "method = \"exact\"", "method = \"exact\"\ntolerance = 1e-9"),
         "solver.tolerance"},
        {"unknown solver method", replace(good, "method = \"exact\"", "method = \"rk4\""), "solver.method"},
        {"ratios that damp the high modes negatively (beta < 0)",
         replace(good, "ratios = [0.005, 0.005]", "ratios = [0.005, 0.0]"), "damping.ratios"},
        {"ratios that damp mode 1 negatively (alpha < 0)",
         replace(replace(good, "ratios = [0.005, 0.005]", "ratios = [0.0, 0.005]"), "modes = [1, 2]",
                 "modes = [2, 3]"),
         "damping.ratios"},
    };
    for (const BadCase& c : cases) {
        const std::string dir = test::make_temp_dir();
        const std::string path = dir + "/bad.toml";
        std::ofstream(path) << c.text;
        const std::string out = dir + "/out";
        for (const bool json_flag : {false, true}) {
            std::vector<std::string> args{"simulate", path, "--out", out};
            if (json_flag) args.push_back("--json");
            const auto r = run_vibroimpact(args);
            const std::string what = std::string(c.what) + (json_flag ? " (--json)" : "");
            EXPECT_EQ(r.exit_code, 2) << what << ": " << r.err;
            EXPECT_TRUE(test::is_one_error_line(r.err)) << what << ": " << r.err;
            EXPECT_EQ(r.err.rfind("vibroimpact: error: " + path, 0), 0u) << what << ": names no file: " << r.err;
            EXPECT_NE(r.err.find(std::string(c.key) + ":"), std::string::npos) << what << ": names no key: " << r.err;
            EXPECT_TRUE(r.out.empty()) << what << ": " << r.out;
            EXPECT_FALSE(fs::exists(out)) << what << " wrote output";
        }
        fs::remove_all(dir);
    }
}

// A coarse smallest search step leaves release steps the solver cannot prove free of a contact: the
// run completes, and says so on stderr (one line naming the case and the remedy) and in the summary.
TEST(CliSimulateWarnings, UnprovenEventSearchIsReported) {
    const std::string good = read_text(test::source_path(kExample));
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/coarse.toml";
    std::ofstream(path) << replace(good, "method = \"exact\"", "method = \"exact\"\nmin_search_step = 1e-3");
    const auto r = run_vibroimpact({"simulate", path, "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("vibroimpact: warning: " + path + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("solver.min_search_step"), std::string::npos) << r.err;
    const json j = json::parse(r.out);
    EXPECT_GT(j["solver"]["unproven_excess"].get<double>(), 1e-9);
    EXPECT_EQ(j["resolved"]["solver"]["min_search_step"].get<double>(), 1e-3);
    fs::remove_all(dir);
}

TEST(CliSimulateBadInput, MissingFileAndUnknownOptionExitTwo) {
    auto r = run_vibroimpact({"simulate", "/nonexistent/case.toml", "--json"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("/nonexistent/case.toml"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
    r = run_vibroimpact({"simulate"});
    EXPECT_EQ(r.exit_code, 2);
    r = run_vibroimpact({"simulate", test::source_path(kExample), "--frobnicate"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(r.out.empty());
}

TEST(CliSimulateHelp, MentionsOut) {
    const auto r = run_vibroimpact({"simulate", "--help"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("--out"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--json"), std::string::npos) << r.out;
}

TEST(CliSimulateCvodeState, SummarySaysWhichCoordinatesCvodeIntegrated) {
    const std::string kSwitch = test::source_path("examples/switch/cantilever_switch.toml");
    const auto state_of = [&](const std::string& reduced_modes) {
        const auto r = test::run_vibroimpact({"simulate", kSwitch, "--json", "--set", "solver.horizon=2 us", "--set",
                                              "solver.reduced_modes=" + reduced_modes});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const json j = json::parse(r.out);
        EXPECT_EQ(j["solver"]["method"], "cvode");
        return j["solver"]["state"];
    };
    // The electrode covers most of the beam: the full model runs in the FE DOFs, a reduced one in its modes.
    EXPECT_EQ(state_of("0"), "fe_dofs");
    EXPECT_EQ(state_of("8"), "modal");
    const auto exact = test::run_vibroimpact({"simulate", test::source_path("examples/paper/free_impact_tip.toml"), "--json"});
    ASSERT_EQ(exact.exit_code, 0) << exact.err;
    EXPECT_FALSE(json::parse(exact.out)["solver"].contains("state"));
}

}  // namespace
}  // namespace vi
