// `vibroimpact fit --features` (calibration/feature_fit): synthetic recovery of the contact
// stiffness and the first damping ratio from the period, the impact duration and the quality
// factor; feature sets that cannot determine a parameter reported as such; bad feature files.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "calibration/feature_fit.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

Case paper_case() { return read_case_file(test::source_path("examples/paper/free_impact_tip.toml")); }

// Features of `truth` plus Gaussian noise of each sigma (fixed seed), as a file would give them.
MeasuredFeatures measured(const Case& truth, const std::vector<std::pair<std::string, double>>& sigmas, unsigned seed) {
    MeasuredFeatures m;
    m.file = "synthetic";
    for (const auto& [name, sigma] : sigmas) m.features.push_back({name, 0.0, sigma, m.features.size() + 2});
    const std::vector<double> exact = model_features(truth, {}, {}, m);
    std::mt19937 gen(seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (std::size_t k = 0; k < exact.size(); ++k) {
        m.features[k].value = exact[k] + m.features[k].sigma * noise(gen);
        std::printf("  %s: model %.6g, measured %.6g +- %.3g\n", m.features[k].name.c_str(), exact[k], m.features[k].value,
                    m.features[k].sigma);
    }
    return m;
}

// Kc = 1000 N/m and zeta_1 = 0.005 from T (5.45 us +- 10 ns), T2 (1.05 us +- 10 ns) and Q1 (100 +- 3),
// starting 30 % and 40 % off.
TEST(FitFeatures, RecoversKcAndZeta1FromPeriodImpactDurationAndQualityFactor) {
    const Case truth = paper_case();
    const MeasuredFeatures data = measured(truth, {{"T_s", 0.01e-6}, {"T2_s", 0.01e-6}, {"q1", 3.0}}, 11u);
    Case start = truth;
    start.supports[0].stiffness = 1300.0;
    start.damping.ratio1 = 0.007;
    const std::vector<FitParameter> params = {parse_fit_parameter("supports[0].stiffness", start),
                                              parse_fit_parameter("damping.ratios[0]", start)};
    const FitResult r = fit_features(start, params, data);
    ASSERT_TRUE(r.converged) << r.message;
    const double truth_values[2] = {1000.0, 0.005};
    std::printf("fit: %d iterations, %d simulations\n", r.iterations, r.simulations);
    for (std::size_t i = 0; i < 2; ++i) {
        std::printf("  %s: %.6g +- %.3g (95 %%: %.6g .. %.6g), truth %.6g\n", params[i].name().c_str(), r.estimate[i],
                    r.std_error[i], r.ci_low[i], r.ci_high[i], truth_values[i]);
        EXPECT_TRUE(r.undetermined[i].empty()) << r.undetermined[i];
        EXPECT_LE(r.ci_low[i], truth_values[i]) << params[i].name();
        EXPECT_GE(r.ci_high[i], truth_values[i]) << params[i].name();
    }
    // Q1 = 1 / (2 zeta_1) alone fixes zeta_1: its standard error is Q's relative one times zeta_1.
    EXPECT_NEAR(r.std_error[1] / r.estimate[1], 3.0 / data.features[2].value, 0.02 * 3.0 / data.features[2].value);
}

// Q1 does not depend on the contact stiffness; f1 depends on E and rho only through E / rho.
TEST(FitFeatures, AFeatureSetThatCannotDetermineAParameterSaysSo) {
    const Case truth = paper_case();
    {
        const MeasuredFeatures data = measured(truth, {{"q1", 3.0}}, 5u);
        const std::vector<FitParameter> params = {parse_fit_parameter("supports[0].stiffness", truth),
                                                  parse_fit_parameter("damping.ratios[0]", truth)};
        const FitResult r = fit_features(truth, params, data);
        EXPECT_EQ(r.undetermined[0], "the data do not depend on it");
        EXPECT_TRUE(std::isnan(r.std_error[0]));
        EXPECT_TRUE(r.undetermined[1].empty()) << r.undetermined[1];
        EXPECT_TRUE(std::isfinite(r.std_error[1]));
    }
    {
        const MeasuredFeatures data = measured(truth, {{"f1_hz", 1e3}}, 6u);
        const std::vector<FitParameter> params = {parse_fit_parameter("material.youngs_modulus", truth),
                                                  parse_fit_parameter("material.density", truth)};
        const FitResult r = fit_features(truth, params, data);
        for (std::size_t i = 0; i < 2; ++i) {
            EXPECT_NE(r.undetermined[i].find("trades off with"), std::string::npos) << r.undetermined[i];
        }
        // What f1 fixes: E / rho, to the measurement's 1e3 Hz in 1.1e5 (twice, relative, for a square root).
        const double ratio = r.estimate[0] / r.estimate[1] / (truth.material.youngs_modulus / truth.material.density);
        EXPECT_NEAR(ratio, 1.0, 2 * 3 * 1e3 / data.features[0].value);
    }
}

// Several starts on threads: the same outcome for any thread count; through the command, the table
// of starts in fit.json.
TEST(FitFeatures, SeveralStartsGiveTheSameResultOnAnyThreadCount) {
    const Case truth = paper_case();
    const MeasuredFeatures data = measured(truth, {{"f1_hz", 500.0}, {"q1", 3.0}}, 8u);
    Case start = truth;
    start.material.youngs_modulus = 150e9;
    start.damping.ratio1 = 0.008;
    const std::vector<FitParameter> params = {parse_fit_parameter("material.youngs_modulus=100e9:300e9", start),
                                              parse_fit_parameter("damping.ratios[0]", start)};
    FitOptions o;
    o.starts = 5;
    o.threads = 1;
    const FitResult serial = fit_features(start, params, data, o);
    o.threads = 3;
    const FitResult threaded = fit_features(start, params, data, o);
    ASSERT_EQ(serial.starts.size(), 5u);
    EXPECT_EQ(serial.best, threaded.best);
    EXPECT_EQ(serial.estimate, threaded.estimate);
    EXPECT_EQ(serial.std_error, threaded.std_error);
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_EQ(serial.starts[k].start, threaded.starts[k].start);
        EXPECT_EQ(serial.starts[k].end, threaded.starts[k].end);
        EXPECT_EQ(serial.starts[k].cost, threaded.starts[k].cost);
    }
    // The first start is the case's values; the others lie within the bounds (E) or within a factor
    // 2 of the start (zeta_1, unbounded).
    EXPECT_EQ(serial.starts[0].start, (std::vector<double>{150e9, 0.008}));
    for (const StartRun& s : serial.starts) {
        EXPECT_GE(s.start[0], 100e9);
        EXPECT_LE(s.start[0], 300e9);
        EXPECT_GE(s.start[1], 0.004);
        EXPECT_LE(s.start[1], 0.016);
        EXPECT_TRUE(s.converged) << s.message;
    }
    // One smooth minimum: every start ends there.
    EXPECT_EQ(serial.distinct_minima, 1);

    const std::string dir = test::make_temp_dir();
    std::ofstream(dir + "/f.csv") << "name,value,sigma\nf1_hz," << data.features[0].value << ",500\nq1,"
                                  << data.features[1].value << ",3\n";
    const auto r = test::run_vibroimpact({"fit", test::source_path("examples/paper/free_impact_tip.toml"), "--features",
                                          dir + "/f.csv", "--fit", "material.youngs_modulus=100e9:300e9", "--fit",
                                          "damping.ratios[0]", "--starts", "4", "--threads", "2", "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Starts: 4, 4 converged"), std::string::npos) << r.out;
    const std::string json = test::read_text(dir + "/out/fit.json");
    EXPECT_NE(json.find("\"distinct_minima\": 1"), std::string::npos) << json;
    EXPECT_NE(json.find("\"feature_residuals\""), std::string::npos);
    fs::remove_all(dir);
}

TEST(FitFeatures, BadFeatureFilesAreExit2NamingFileAndLine) {
    const std::string dir = test::make_temp_dir();
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir + "/" + name) << text;
        return dir + "/" + name;
    };
    const auto message = [](const std::string& path) {
        try {
            (void)read_measured_features(path);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string unknown = write("u.csv", "name,value,sigma\nT_s,5e-6,1e-8\nperiod,5e-6,1e-8\n");
    const std::string zero_sigma = write("z.csv", "name,value,sigma\n# a comment\nT_s,5e-6,0\n");
    const std::string nan = write("n.csv", "name,sigma,value\nq1,3,nan\n");
    const std::string twice = write("t.csv", "name,value,sigma\nq1,100,3\nq1,90,3\n");
    const std::string header = write("h.csv", "name,value\nq1,100\n");
    const std::string empty = write("e.csv", "name,value,sigma\n");
    EXPECT_NE(message(unknown).find("u.csv:3: name: 'period' is not a feature"), std::string::npos) << message(unknown);
    EXPECT_NE(message(zero_sigma).find("z.csv:3: T_s: sigma must be positive"), std::string::npos) << message(zero_sigma);
    EXPECT_NE(message(nan).find("n.csv:2: q1: value 'nan' is not a finite number"), std::string::npos) << message(nan);
    EXPECT_NE(message(twice).find("t.csv:3: q1 is given twice (first on line 2)"), std::string::npos) << message(twice);
    EXPECT_NE(message(header).find("h.csv:1: the header row must name"), std::string::npos) << message(header);
    EXPECT_NE(message(empty).find("e.csv:1: no feature"), std::string::npos) << message(empty);

    // Through the command: exit 2, one line naming FILE:LINE, nothing written.
    const std::string tip = test::source_path("examples/paper/free_impact_tip.toml");
    const auto run = [&](const std::string& case_path, const std::string& features) {
        return test::run_vibroimpact({"fit", case_path, "--features", features, "--fit", "supports[0].stiffness", "--out",
                                      dir + "/out"});
    };
    auto r = run(tip, unknown);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("u.csv:3:"), std::string::npos) << r.err;
    // A pull-in voltage for a case without electrodes.
    r = run(tip, write("v.csv", "name,value,sigma\nq1,100,3\nV_PI_V,40,1\n"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("v.csv:3: V_PI_V: the case has no electrode"), std::string::npos) << r.err;
    // A feature the model does not produce at the start: a period needs a second impact, and 3 us
    // of horizon see only the first.
    std::string text = test::read_text(tip);
    const std::size_t at = text.find("horizon = \"150 us\"");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 18, "horizon = \"3 us\"");
    const std::string short_case = write("short.toml", text);
    r = run(short_case, write("p.csv", "name,value,sigma\nq1,100,3\nT_s,5e-6,1e-8\n"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("p.csv:3: T_s: the model gives none"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
