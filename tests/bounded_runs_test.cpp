// Work in proportion to the question: runs of the switch examples that a designer's (or a fuzzer's)
// change made run for minutes either answer as quickly as the example does, or are refused before
// any work with one line naming the file, the line and the key, the reason and the limit (exit 2,
// nothing written). Each runs as a user runs it, in a child process; the limit only catches a hang
// (the seconds are printed, never asserted).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "io/case_reader.hpp"
#include "model/run_estimate.hpp"

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

// Meshes past what a command can do in proportion: the pull-in trace (its Newton steps grow with K's
// roundoff and cost the square of the DOFs an electrode faces: m = 1000 gave no answer in 120 s),
// air-q's ring-downs, a transient on the full model with an electrode, and switch-report, which
// traced the pull-in before the transient's own limit refused the case.
TEST(BoundedRuns, MeshesBeyondWhatACommandTakesAreRefusedOnBeamElements) {
    const std::string dir = test::make_temp_dir();
    const auto mesh = [&](int m) {
        return switch_variant(dir, "m" + std::to_string(m) + ".toml",
                              {{"elements = 50", "elements = " + std::to_string(m)}});
    };
    const std::string out = dir + "/out";
    for (const int m : {1000, 2000}) {
        expect_refused({"pullin", mesh(m), "--out", out}, mesh(m) + ":19: beam.elements",
                       {std::to_string(m) + " elements are more than the pull-in trace takes", "at most 400"}, out, "pullin");
        expect_refused({"pullin", mesh(m), "--dynamic", "--out", out}, mesh(m) + ":19: beam.elements", {"at most 400"}, out,
                       "pullin --dynamic");
    }
    // The bridge example stretches: its trace takes at most 200 elements (26 s of CPU at 400).
    std::string bridge = test::read_text(test::source_path("examples/switch/bridge_switch.toml"));
    bridge.replace(bridge.find("elements = 40 "), 14, "elements = 400 ");
    test::write_text(dir + "/bridge400.toml", bridge);
    for (const char* dynamic : {"", "--dynamic"}) {
        std::vector<std::string> args{"pullin", dir + "/bridge400.toml", "--out", out};
        if (*dynamic) args.emplace_back(dynamic);
        expect_refused(args, dir + "/bridge400.toml:24: beam.elements",
                       {"400 elements are more than the pull-in trace takes with stretching = true (at most 200"}, out,
                       "pullin of the stretching bridge at m = 400");
    }
    for (const int m : {400, 1000}) {
        expect_refused({"air-q", mesh(m), "--out", out}, mesh(m) + ":19: beam.elements",
                       {"more than air-q takes (at most 100", "use fewer"}, out, "air-q");
    }
    expect_refused({"switch-report", mesh(1000), "--out", out}, mesh(1000) + ":19: beam.elements",
                   {"more than a transient with solver.method = \"cvode\" takes (at most 400"}, out, "switch-report m = 1000");
    // The full model with its electrode at m = 400 is within the limits: its state is in the FE DOFs.
    Case fine = read_case_file(mesh(400));
    for (const CaseProblem& p : check_transient_run(fine, true, 1e12)) EXPECT_NE(p.key, "beam.elements") << p.message;
}

// What the refusal suggests answers: the example at m = 400 on a reduced model of 16 modes closes when
// the example does (3.17244 us); pullin --dynamic at m = 200 bisects on reduced models and confirms
// its bracket on a finer reduced one, never the full model the limit refuses.
TEST(BoundedRuns, AFineMeshAnswersOnAReducedModel) {
    const std::string dir = test::make_temp_dir();
    const json fine = simulate_json(switch_variant(dir, "m400.toml", {{"elements = 50", "elements = 400"},
                                                                      {"rtol = 1e-8", "rtol = 1e-8\nreduced_modes = 16"}}),
                                    "m = 400, 16 modes");
    const json example = simulate_json(test::source_path("examples/switch/cantilever_switch.toml"), "example");
    ASSERT_TRUE(fine.is_object() && example.is_object());
    EXPECT_EQ(fine["switching"]["state"], "closed");
    EXPECT_NEAR(fine["switching"]["closing_time_s"].get<double>(), example["switching"]["closing_time_s"].get<double>(),
                1e-5 * example["switching"]["closing_time_s"].get<double>());
    const CommandResult r = run({"pullin", switch_variant(dir, "m200.toml", {{"elements = 50", "elements = 200"}}),
                                 "--dynamic", "--json"},
                                "pullin --dynamic, m = 200");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json d = json::parse(r.out)["dynamic"];
    EXPECT_GT(d["confirmed_on_reduced_modes"].get<int>(), 0) << d;
    for (const json& t : d["trials"]) EXPECT_GT(t["reduced_modes"].get<int>(), 0) << t;
    EXPECT_NEAR(d["ratio_to_static"].get<double>(), 0.912, 0.002);
}

// Tolerances and drives that ask for work without end: an rtol below 1e-12 (the error test then
// resolves the roundoff of the right-hand side), a sine above every bending frequency of the mesh,
// a sine of more periods than solver.max_steps can take; refused on their keys before the run.
TEST(BoundedRuns, ToleranceAndDriveBeyondWhatTheStepsCanTakeAreRefused) {
    const std::string dir = test::make_temp_dir();
    const std::string out = dir + "/out";
    const std::string tight = switch_variant(dir, "rtol.toml", {{"rtol = 1e-8", "rtol = 1e-13"}});
    expect_refused({"simulate", tight, "--out", out}, tight + ":56: solver.rtol", {"must be at least 1e-12"}, out, "rtol 1e-13");
    const auto sine = [&](const std::string& name, const std::string& frequency, const std::string& solver_extra) {
        return switch_variant(dir, name, {{"waveform = \"step\"", "waveform = \"sine\"\nfrequency = \"" + frequency + "\""},
                                          {"t_on = \"0 us\"", ""},
                                          {"rtol = 1e-8", "rtol = 1e-8" + solver_extra}});
    };
    const std::string fast = sine("fast.toml", "1e12 Hz", "");
    expect_refused({"simulate", fast, "--out", out}, fast + ":47: electrodes[0].frequency",
                   {"above every bending frequency of the mesh", "50 elements"}, out, "sine at 1e12 Hz");
    const std::string many = sine("many.toml", "10 MHz", "\nmax_steps = 1000");
    expect_refused({"simulate", many, "--out", out}, many + ":47: electrodes[0].frequency",
                   {"500 periods", "more than solver.max_steps = 1000"}, out, "sine of 500 periods");
}

// solver.max_steps reached says what raises it, and, on a full model without damping, that the
// mesh's highest mode rings and a reduced model or damping is the way out.
TEST(BoundedRuns, TheStepLimitNamesItsKeyAndTheUndampedTopMode) {
    const std::string dir = test::make_temp_dir();
    const std::string undamped = switch_variant(dir, "undamped.toml", {{"ratios = [0.005, 0.005]", "ratios = [0, 0]"},
                                                                       {"rtol = 1e-8", "rtol = 1e-8\nmax_steps = 2000"}});
    const CommandResult r = run({"simulate", undamped}, "undamped, 2000 steps");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("more than solver.max_steps = 2000"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("keeps its highest mode"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("set solver.reduced_modes"), std::string::npos) << r.err;
    const std::string damped = switch_variant(dir, "damped.toml", {{"rtol = 1e-8", "rtol = 1e-8\nmax_steps = 1000"}});
    const CommandResult d = run({"simulate", damped}, "damped, 1000 steps");
    EXPECT_EQ(d.exit_code, 1) << d.err;
    EXPECT_NE(d.err.find("more than solver.max_steps = 1000 steps before the horizon"), std::string::npos) << d.err;
    EXPECT_NE(d.err.find("raise solver.max_steps"), std::string::npos) << d.err;
    EXPECT_EQ(d.err.find("keeps its highest mode"), std::string::npos) << d.err;
}

// The number in `text` after `label` (0 when there is none).
double number_after(const std::string& text, const std::string& label) {
    const auto at = text.find(label);
    return at == std::string::npos ? 0.0 : std::strtod(text.c_str() + at + label.size(), nullptr);
}

// The switch example without damping on the full model: CVODE follows the mesh's undamped top mode
// (4.85 GHz) at a steady pace once the voltage step has set it ringing, about 4 million steps over
// the 50 us horizon. The run does not spend the whole default budget of solver.max_steps to learn
// that: it ends at a tenth of it from the pace of its last window of steps (exit 1, nothing written), with the steps
// the horizon needs, the limit and the keys that help; so does switch-report, whose transient is the
// same. The reduced model of 16 modes, also undamped, answers.
// The step budget these pace tests run at: the default in Release; a tenth in the short run of the
// sanitizer builds (tests/CMakeLists.txt, VI_SHORT_TESTS), where half a million steps take minutes.
// Each case edit that sets it, and the window of steps the pace is measured over (max(1000, budget / 20)).
#if VI_SHORT_TESTS
const std::pair<std::string, std::string> kBudgetEdit{"rtol = 1e-8", "rtol = 1e-8\nmax_steps = 100000"};
const std::string kBudget = "100000";
const std::string kWindow = "5000";
#else
const std::pair<std::string, std::string> kBudgetEdit{"rtol = 1e-8", "rtol = 1e-8"};
const std::string kBudget = "1000000";
const std::string kWindow = "50000";
#endif

TEST(BoundedRuns, AnUndampedFullModelEndsOnItsPaceBeforeTheStepBudget) {
    const std::string dir = test::make_temp_dir();
    const std::string out = dir + "/out";
    const std::string undamped = switch_variant(dir, "undamped.toml", {{"ratios = [0.005, 0.005]", "ratios = [0, 0]"}, kBudgetEdit});
    for (const char* command : {"simulate", "switch-report"}) {
        const CommandResult r = run({command, undamped, "--out", out}, command);
        EXPECT_EQ(r.exit_code, 1) << command << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find("vibroimpact: failure: solve_cvode: at the pace of its last 1 window of " + kWindow + " steps"),
                  std::string::npos)
            << r.err;
        // The steps it carries to the horizon exceed the budget and come near what the whole run
        // takes with the budget raised (measured: 4.41e6 steps with the state in the FE DOFs). The
        // sanitizer builds' short window ends at t = 97 ns, while the ringing still sets in, and
        // projects 5.1e6: within a quarter of the whole run.
        const double need = number_after(r.err, "the horizon needs about ");
        EXPECT_GT(need, std::stod(kBudget)) << r.err;
        EXPECT_LT(need, 1.25 * 4.41e6) << r.err;
        EXPECT_NE(r.err.find("more than solver.max_steps = " + kBudget +
                             ": the full model without damping keeps its highest mode (4.85e+09 Hz) ringing"),
                  std::string::npos)
            << r.err;
        EXPECT_NE(r.err.find("set solver.reduced_modes (e.g. 16) or add [damping], or raise solver.max_steps"),
                  std::string::npos)
            << r.err;
        EXPECT_FALSE(fs::exists(out)) << command;
    }
    const std::string reduced = switch_variant(dir, "reduced.toml", {{"ratios = [0.005, 0.005]", "ratios = [0, 0]"},
                                                                     {"rtol = 1e-8", "rtol = 1e-8\nreduced_modes = 16"}});
    const json j = simulate_json(reduced, "undamped, reduced to 16 modes");
    EXPECT_TRUE(j.contains("switching")) << j.dump();
}

// The switch example with Rayleigh ratios of 1e-6: its top modes are damped (about 6e-3 of critical)
// but the bouncing keeps exciting them, and CVODE keeps a pace of about 54 000 steps per us, some 2.7
// million steps over the horizon. Three windows in a row at that pace, once half the budget is spent,
// end the run (exit 1, nothing written), not an impact's burst; the message names the budget and its key.
TEST(BoundedRuns, ASustainedPaceBeyondTheStepBudgetEndsTheRun) {
    const std::string dir = test::make_temp_dir();
    const std::string out = dir + "/out";
    const std::string light = switch_variant(dir, "light.toml", {{"ratios = [0.005, 0.005]", "ratios = [1e-6, 1e-6]"}, kBudgetEdit});
    const CommandResult r = run({"simulate", light, "--out", out}, "ratios 1e-6");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("vibroimpact: failure: solve_cvode: at the pace of its last 3 windows of " + kWindow + " steps"),
              std::string::npos)
        << r.err;
    EXPECT_GT(number_after(r.err, "the horizon needs about "), std::stod(kBudget)) << r.err;
    EXPECT_NE(r.err.find("more than solver.max_steps = " + kBudget + "; raise solver.max_steps"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out));
}

// air-q of a beam under two film spans (the switch example with a second electrode from the clamp
// to x/l = 0.1): every pressure's ring-down answers with the Q of the film's modal damping, to the
// 1e-3 that 10 periods of a ring-down at Q up to 1e6 keep (tests/cases/air_q_two_films.toml).
TEST(BoundedRuns, AirQOfABeamUnderTwoFilmSpansAnswers) {
    const std::string dir = test::make_temp_dir();
    const std::string out = dir + "/out";
    const CommandResult r = run({"air-q", test::source_path("tests/cases/air_q_two_films.toml"), "--out", out}, "air-q, two films");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> rows = [&] {
        std::vector<std::string> v;
        std::istringstream in(test::read_text(out + "/air_q.csv"));
        for (std::string line; std::getline(in, line);) v.push_back(line);
        return v;
    }();
    ASSERT_EQ(rows.size(), 18u) << "a header and 17 pressures";
    EXPECT_EQ(rows.front(), "pressure_pa,knudsen,viscosity_ratio,squeeze_number,q_modal,q_ringdown,maxima");
    for (std::size_t i = 1; i < rows.size(); ++i) {
        std::vector<double> x;
        std::istringstream in(rows[i]);
        for (std::string cell; std::getline(in, cell, ',');) x.push_back(std::strtod(cell.c_str(), nullptr));
        ASSERT_EQ(x.size(), 7u) << rows[i];
        EXPECT_NEAR(x[5], x[4], 3e-3 * x[4]) << rows[i];
        EXPECT_EQ(x[6], 10.0) << rows[i];
    }
}

}  // namespace
}  // namespace vi
