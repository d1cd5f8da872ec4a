// `vibroimpact uq` end to end: exact propagation through the pull-in law V_PI ~ t^1.5 g^1.5 with
// thickness and gap lognormal (the estimates against their intervals), the Sobol indices of that
// law against their closed forms, resume after a stop, thread counts and MPI ranks giving the same
// uq.json byte for byte, failed samples counted, the figures, the progress report, and the refusals
// of bad input.

#include <gtest/gtest.h>
#include <signal.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/mpi_launch.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "uq/distribution.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CommandResult;
using test::read_text;
using test::run_vibroimpact;

const std::string kCase = test::source_path("tests/cases/full_electrode_cantilever.toml");
// Sigma of log t and of log g.
constexpr double kSigmaT = 0.03, kSigmaG = 0.04;
const std::vector<std::string> kVary = {"--vary", "beam.thickness=lognormal:2um:0.03", "--vary",
                                        "electrodes[0].gap=lognormal:2um:0.04"};

std::vector<std::string> uq_args(const std::string& out, const std::vector<std::string>& more) {
    std::vector<std::string> a{"uq", kCase, "--analysis", "pullin"};
    a.insert(a.end(), kVary.begin(), kVary.end());
    a.insert(a.end(), {"--out", out});
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

// V_PI at the medians (t = g = 2 um), from the pullin command.
double median_pullin_voltage() {
    const CommandResult r = run_vibroimpact({"pullin", kCase, "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out)["pullin"]["voltage_V"].get<double>();
}

bool within(const json& interval, double v) {
    return interval.is_array() && interval[0].get<double>() <= v && v <= interval[1].get<double>();
}

// log V_PI = log V0 + 1.5 log(t / t0) + 1.5 log(g / g0) is normal with mean log V0 and SD
// s = 1.5 sqrt(sigma_t^2 + sigma_g^2): V_PI is lognormal with median V0, so its mean is
// V0 exp(s^2 / 2), its SD the mean times sqrt(exp(s^2) - 1), its p-quantile V0 exp(s z_p).
TEST(CliUq, PullinSpreadPropagatesExactlyThroughTheThreeHalvesLaw) {
    const std::string dir = test::make_temp_dir();
    const CommandResult r = run_vibroimpact(uq_args(dir + "/out", {"--samples", "1000", "--seed", "1", "--spec",
                                                                   "pullin_voltage_v<=60", "--json"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j, json::parse(read_text(dir + "/out/uq.json")));
    EXPECT_EQ(j["failed"], 0);
    const double v0 = median_pullin_voltage();
    const double s = 1.5 * std::hypot(kSigmaT, kSigmaG);
    const Distribution law = {Distribution::Kind::lognormal, v0, s, 0.0, 0.0};
    const json& c = j["columns"]["pullin_voltage_v"];
    EXPECT_EQ(c["n"], 1000);
    std::printf("mean %.6g in [%.6g, %.6g] (exact %.6g); std %.6g in [%.6g, %.6g] (exact %.6g)\n", c["mean"].get<double>(),
                c["mean_ci"][0].get<double>(), c["mean_ci"][1].get<double>(), law.mean(), c["std"].get<double>(),
                c["std_ci"][0].get<double>(), c["std_ci"][1].get<double>(), law.std_dev());
    EXPECT_TRUE(within(c["mean_ci"], law.mean()));
    EXPECT_TRUE(within(c["std_ci"], law.std_dev()));
    for (const char* p : {"5", "95"}) {
        const double exact = law.quantile(std::stod(p) / 100.0);
        std::printf("q%s %.6g in [%.6g, %.6g] (exact %.6g)\n", p, c["quantiles"][p].get<double>(),
                    c["quantile_ci"][p][0].get<double>(), c["quantile_ci"][p][1].get<double>(), exact);
        EXPECT_TRUE(within(c["quantile_ci"][p], exact)) << p;
    }
    // The yield's interval holds the exact probability P(V_PI <= 60 V) = Phi(log(60 / V0) / s).
    const json& y = c["yield"][0];
    const double p60 = 0.5 * std::erfc(-std::log(60.0 / v0) / s / std::sqrt(2.0));
    std::printf("yield %.4f in [%.4f, %.4f] (exact %.4f)\n", y["yield"].get<double>(), y["ci"][0].get<double>(),
                y["ci"][1].get<double>(), p60);
    EXPECT_TRUE(within(y["ci"], p60));
    EXPECT_EQ(y["evaluated"], 1000);
    // samples.csv: the inputs, every column, the status.
    const std::string csv = read_text(dir + "/out/samples.csv");
    EXPECT_EQ(csv.rfind("beam.thickness_m,electrodes[0].gap_m,rest_capacitance_f,pullin_voltage_v,", 0), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1001);
    fs::remove_all(dir);
}

// With V = V0 e^a e^b, a = 1.5 log(t / t0) and b = 1.5 log(g / g0) independent normals of SD s_a,
// s_b: S_a = (e^{s_a^2} - 1) / (e^{s_a^2 + s_b^2} - 1) and S_Ta = 1 - S_b (docs/uq.md, which also
// gives the log-linear form's s_a^2 / (s_a^2 + s_b^2)). The estimates lie within their intervals.
TEST(CliUq, SobolIndicesOfThePullinLaw) {
    const std::string dir = test::make_temp_dir();
    const CommandResult r = run_vibroimpact(uq_args(dir + "/out", {"--samples", "256", "--method", "sobol",
                                                                   "--sensitivity", "--json"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["runs"], 256 * 4);
    const double a2 = std::pow(1.5 * kSigmaT, 2), b2 = std::pow(1.5 * kSigmaG, 2);
    const double st = std::expm1(a2) / std::expm1(a2 + b2), sg = std::expm1(b2) / std::expm1(a2 + b2);
    const json& sobol = j["columns"]["pullin_voltage_v"]["sobol"];
    const std::pair<const char*, double> first[] = {{"beam.thickness", st}, {"electrodes[0].gap", sg}};
    for (const auto& [path, exact] : first) {
        const json& x = sobol[path];
        std::printf("%s: first %.4f in [%.4f, %.4f], total %.4f in [%.4f, %.4f]; exact %.4f and %.4f\n", path,
                    x["first"].get<double>(), x["first_ci"][0].get<double>(), x["first_ci"][1].get<double>(),
                    x["total"].get<double>(), x["total_ci"][0].get<double>(), x["total_ci"][1].get<double>(), exact,
                    1.0 - (path == std::string("beam.thickness") ? sg : st));
        EXPECT_TRUE(within(x["first_ci"], exact)) << path;
        EXPECT_TRUE(within(x["total_ci"], 1.0 - (path == std::string("beam.thickness") ? sg : st))) << path;
    }
    EXPECT_EQ(j["columns"]["pullin_voltage_v"]["sobol_rows"], 256);
    fs::remove_all(dir);
}

// A study stopped by SIGINT and resumed writes the uq.json of an uninterrupted one, byte for byte;
// and so does one on another number of threads.
TEST(CliUq, ResumeAndThreadCountsGiveTheSameUqJson) {
    const std::string dir = test::make_temp_dir();
    const std::vector<std::string> common = {"--samples", "64", "--method", "lhs", "--sensitivity", "--spec",
                                             "pullin_voltage_v>=50", "--point-timeout", "0"};
    std::vector<std::string> one = common, two = common;
    one.insert(one.end(), {"--threads", "1"});
    two.insert(two.end(), {"--threads", "2"});
    ASSERT_EQ(run_vibroimpact(uq_args(dir + "/one", one)).exit_code, 0);
    ASSERT_EQ(run_vibroimpact(uq_args(dir + "/two", two)).exit_code, 0);
    const std::string reference = read_text(dir + "/one/uq.json");
    EXPECT_EQ(read_text(dir + "/two/uq.json"), reference);
    EXPECT_EQ(read_text(dir + "/two/samples.csv"), read_text(dir + "/one/samples.csv"));

    std::vector<std::string> argv{test::vibroimpact_path()};
    for (const std::string& a : uq_args(dir + "/stopped", one)) argv.push_back(a);
    test::ChildProcess child(argv);
    const std::string journal = dir + "/stopped/sweep.journal";
    const auto lines = [&] {
        const std::string t = read_text(journal);
        return static_cast<std::size_t>(std::count(t.begin(), t.end(), '\n'));
    };
    ASSERT_TRUE(test::wait_until([&] { return lines() >= 4 + 40 || !child.running(); }, test::kHangLimitSeconds));
    child.signal(SIGINT);
    const CommandResult stopped = child.wait();
    if (stopped.exit_code == 0) GTEST_SKIP() << "the study finished before the signal (a very fast machine)";
    EXPECT_EQ(stopped.exit_code, 130) << stopped.err;
    EXPECT_NE(stopped.err.find("uq interrupted"), std::string::npos) << stopped.err;
    EXPECT_FALSE(fs::exists(dir + "/stopped/uq.json"));
    std::vector<std::string> resume = one;
    resume.push_back("--resume");
    const CommandResult resumed = run_vibroimpact(uq_args(dir + "/stopped", resume));
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_NE(resumed.out.find("from the journal"), std::string::npos);
    EXPECT_EQ(read_text(dir + "/stopped/uq.json"), reference);
    EXPECT_FALSE(fs::exists(journal));
    fs::remove_all(dir);
}

// Two MPI ranks share the runs and rank 0 writes the uq.json of a single process.
TEST(CliUq, TwoMpiRanksGiveTheSameUqJson) {
    if (const std::string why = test::mpi_unavailable(); !why.empty()) GTEST_SKIP() << "MPI part skipped: " << why;
    const std::string dir = test::make_temp_dir();
    const std::vector<std::string> common = {"--samples", "32", "--sensitivity", "--threads", "1"};
    ASSERT_EQ(run_vibroimpact(uq_args(dir + "/one", common)).exit_code, 0);
    const CommandResult mpi = test::run_mpi(uq_args(dir + "/mpi", common));
    ASSERT_EQ(mpi.exit_code, 0) << mpi.out << mpi.err;
    EXPECT_NE(mpi.out.find("x 2 processes"), std::string::npos) << mpi.out;
    EXPECT_EQ(read_text(dir + "/mpi/uq.json"), read_text(dir + "/one/uq.json"));
    EXPECT_EQ(read_text(dir + "/mpi/samples.csv"), read_text(dir + "/one/samples.csv"));
    fs::remove_all(dir);
}

// Thickness normal with an SD as large as its mean: the negative draws are refused by the case
// checks, counted as failed runs and left out of the statistics, never silently dropped.
TEST(CliUq, FailedSamplesAreCountedAndReported) {
    const std::string dir = test::make_temp_dir();
    const CommandResult r = run_vibroimpact({"uq", kCase, "--analysis", "pullin", "--vary", "beam.thickness=normal:2um:2um",
                                             "--samples", "40", "--out", dir + "/out", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    std::size_t negative = 0;
    std::istringstream csv(read_text(dir + "/out/samples.csv"));
    std::string line;
    std::getline(csv, line);
    while (std::getline(csv, line)) negative += std::stod(line.substr(0, line.find(','))) <= 0.0 ? 1 : 0;
    EXPECT_GT(negative, 0u);
    EXPECT_EQ(j["failed"].get<std::size_t>(), negative);
    EXPECT_EQ(j["failures"].size(), negative);
    EXPECT_EQ(j["columns"]["pullin_voltage_v"]["n"].get<std::size_t>(), 40 - negative);
    EXPECT_NE(r.err.find("runs failed"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

// The chart data of figure `stem` in a report page (the JSON inside its <script class="vi-chart-data">).
json chart_of(const std::string& page, const std::string& stem) {
    const std::size_t fig = page.find("<figure id=\"" + stem + "\"");
    if (fig == std::string::npos) return json();
    const std::string open = "class=\"vi-chart-data\">";
    const std::size_t from = page.find(open, fig);
    const std::size_t to = page.find("</script>", from);
    if (from == std::string::npos || to == std::string::npos) return json();
    return json::parse(page.substr(from + open.size(), to - from - open.size()));
}

// uq.html: the interactive histogram holds the histogram's CSV bins, the Sobol chart uq.json's indices
// with their intervals as interval bars, largest total first, the inputs named on the x axis.
void check_uq_page(const std::string& out) {
    const std::string page = read_text(out + "/uq.html");
    const json j = json::parse(read_text(out + "/uq.json"));
    ASSERT_FALSE(page.empty());
    EXPECT_NE(page.find("uPlot"), std::string::npos);
    const json hist = chart_of(page, "hist_pullin_voltage_v");
    ASSERT_TRUE(hist.is_object());
    const json& bars = hist["panels"][0]["series"][0];
    EXPECT_EQ(bars["style"], "bars");
    double total = 0.0;
    for (const json& n : bars["y"]) total += n.get<double>();
    EXPECT_EQ(total, 64.0);
    ASSERT_EQ(bars["x"].size(), bars["xTo"].size());
    for (std::size_t k = 0; k + 1 < bars["x"].size(); ++k) EXPECT_EQ(bars["xTo"][k], bars["x"][k + 1]);
    EXPECT_EQ(hist["panels"][0]["marks"], json::parse("[60]"));
    const json sobol = chart_of(page, "sobol_pullin_voltage_v");
    ASSERT_TRUE(sobol.is_object());
    const json& panel = sobol["panels"][0];
    ASSERT_EQ(panel["series"].size(), 2u);
    ASSERT_EQ(panel["xTicks"].size(), 2u);
    const json& indices = j["columns"]["pullin_voltage_v"]["sobol"];
    for (std::size_t k = 0; k < 2; ++k) {
        const std::string input = panel["xTicks"][k][1];
        const json& x = indices[input];
        const json& first = panel["series"][0];
        const json& tot = panel["series"][1];
        // 7 significant digits in the chart (plot/chart_json.hpp).
        EXPECT_NEAR(first["y"][k].get<double>(), x["first"].get<double>(), 1e-6 * std::abs(x["first"].get<double>()) + 1e-12);
        EXPECT_NEAR(tot["y"][k].get<double>(), x["total"].get<double>(), 1e-6 * std::abs(x["total"].get<double>()) + 1e-12);
        EXPECT_NEAR(first["yLow"][k].get<double>(), x["first_ci"][0].get<double>(), 1e-6);
        EXPECT_NEAR(tot["yHigh"][k].get<double>(), x["total_ci"][1].get<double>(), 1e-6);
        EXPECT_NEAR(first["x"][k].get<double>(), k - 0.2, 1e-12);
        EXPECT_NEAR(tot["x"][k].get<double>(), k + 0.2, 1e-12);
    }
    EXPECT_GE(indices[panel["xTicks"][0][1].get<std::string>()]["total"].get<double>(),
              indices[panel["xTicks"][1][1].get<std::string>()]["total"].get<double>());
    // The page's tables: the yield with its interval.
    EXPECT_NE(page.find("pullin_voltage_v&lt;=60"), std::string::npos);
}

// The figures of the columns the specs and --plot name: a histogram holding every value, the specs'
// bounds drawn, and the Sobol chart's inputs by falling total index.
TEST(CliUq, HistogramsAndSobolChartsOfTheNamedColumns) {
    const std::string dir = test::make_temp_dir();
    const CommandResult r = run_vibroimpact(uq_args(dir + "/out", {"--samples", "32", "--sensitivity", "--spec",
                                                                   "pullin_voltage_v<=60", "--plot", "pullin_travel_m"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* stem : {"hist_pullin_voltage_v", "sobol_pullin_voltage_v", "hist_pullin_travel_m", "sobol_pullin_travel_m"}) {
        for (const char* ext : {".png", ".svg", ".gp", ".csv"}) {
            EXPECT_TRUE(fs::exists(dir + "/out/" + stem + ext)) << stem << ext;
        }
    }
    EXPECT_FALSE(fs::exists(dir + "/out/hist_rest_capacitance_f.png"));
    // The histogram's counts add up to the base runs (A and B: 64).
    std::istringstream hist(read_text(dir + "/out/hist_pullin_voltage_v.csv"));
    std::string line;
    std::getline(hist, line);
    EXPECT_EQ(line, "from_pullin_voltage_v,to_pullin_voltage_v,samples");
    long total = 0;
    while (std::getline(hist, line)) total += std::stol(line.substr(line.rfind(',') + 1));
    EXPECT_EQ(total, 64);
    EXPECT_NE(read_text(dir + "/out/hist_pullin_voltage_v.gp").find("set arrow from 60, graph 0 to 60, graph 1"),
              std::string::npos);
    // The gap's total index is the larger (0.64 against 0.36): it comes first.
    const std::string sobol = read_text(dir + "/out/sobol_pullin_voltage_v.csv");
    EXPECT_LT(sobol.find("electrodes[0].gap"), sobol.find("beam.thickness")) << sobol;
    check_uq_page(dir + "/out");
    const CommandResult bad = run_vibroimpact(uq_args(dir + "/bad", {"--plot", "pullin_volts"}));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err.rfind("vibroimpact: error: --plot pullin_volts: no numeric column 'pullin_volts'", 0), 0u) << bad.err;
    fs::remove_all(dir);
}

// The progress report of the runs, as sweep's (apps/progress): lines in a pipe.
TEST(CliUq, ReportsItsRunsAsItGoes) {
    const std::string dir = test::make_temp_dir();
    const CommandResult r = run_vibroimpact(uq_args(dir + "/out", {"--samples", "8", "--progress", "lines",
                                                                   "--progress-interval", "0"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("uq: 8/8 runs"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

TEST(CliUq, BadInputIsExit2WithOneLineAndNothingWritten) {
    const std::string dir = test::make_temp_dir();
    const std::string out = dir + "/out";
    const auto refused = [&](const std::vector<std::string>& args, const std::string& message) {
        std::vector<std::string> a{"uq", kCase, "--analysis", "pullin", "--out", out};
        a.insert(a.end(), args.begin(), args.end());
        const CommandResult r = run_vibroimpact(a);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_EQ(r.err, "vibroimpact: error: " + message + "\n");
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(fs::exists(out)) << message;
    };
    refused({"--vary", "beam.thickness=gauss:2um:0.1um"},
            "--vary beam.thickness=gauss:2um:0.1um: unknown distribution 'gauss' (normal:MEAN:SD, uniform:LOW:HIGH, "
            "lognormal:MEDIAN:SIGMA_LOG, truncnormal:MEAN:SD:LOW:HIGH)");
    refused({"--vary", "beam.thickness=normal:2um:0um"}, "--vary beam.thickness=normal:2um:0um: normal: SD must be positive (got 0)");
    refused({"--vary", "beam.thickness=truncnormal:2um:0.1um:2.1um:2.5um"},
            "--vary beam.thickness=truncnormal:2um:0.1um:2.1um:2.5um: truncnormal: the bounds 2.1um .. 2.5um must "
            "hold the mean 2um between them");
    refused({"--vary", "beam.elements=normal:20:2"},
            "--vary beam.elements=normal:20:2: beam.elements takes whole numbers, which a distribution does not give "
            "(sweep it with --set)");
    refused({"--vary", "supports[0].gap=normal:1um:0.1um"},
            "--vary supports[0].gap=normal:1um:0.1um: supports[0]: index out of range (the case has 0 supports)");
    refused({"--vary", "beam.thickness=normal:2um:0.1um", "--sensitivity", "--samples", "31"},
            "--samples 31: --sensitivity needs at least 32 base samples (its bootstrap intervals need that many rows; "
            "it runs N (d + 2) of them)");
    refused({"--vary", "beam.thickness=normal:2um:0.1um", "--spec", "pullin_volts<=40"},
            "--spec pullin_volts<=40: no numeric column 'pullin_volts' in this analysis (one of: rest_capacitance_f, "
            "pullin_voltage_v, pullin_travel_m, pullin_capacitance_f, touchdown_voltage_v, touchdown_travel_m, "
            "touchdown_capacitance_f, release_voltage_v, release_travel_m, release_capacitance_f, collapse_voltage_v, "
            "collapse_travel_m, collapse_capacitance_f, hysteresis_v)");
    refused({"--vary", "beam.thickness=normal:2um:0.1um", "--vary", "beam.thickness=normal:2um:0.2um"},
            "--vary beam.thickness=normal:2um:0.2um: beam.thickness is already varied by --vary "
            "beam.thickness=normal:2um:0.1um");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
