// `vibroimpact fit` (calibration/trajectory_fit): synthetic recovery of the contact stiffness, the
// contact damping ratio and a modal damping ratio from a noisy tip trajectory of the paper's
// free-impact case, intervals that scale with the noise, two parameters that trade off exactly
// reported as such, and bad data files.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "calibration/trajectory_fit.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

// The paper's free-impact case over 40 us, sampled every 40 ns (1001 samples, 7 impacts).
Case truth_case() {
    Case c = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    c.solver.horizon = 40e-6;
    c.solver.output_step = 40e-9;
    return c;
}

// The truth's tip trajectory plus Gaussian noise of `sigma` (fixed seed: the same draws every run).
MeasuredTrajectory synthetic(const Case& truth, double sigma, unsigned seed) {
    SimulationOptions o;
    o.energy = false;
    const SimulationRun run = run_simulation(truth, o);
    MeasuredTrajectory m;
    m.file = "synthetic";
    m.column = "tip_m";
    m.t = run.result.history.t;
    std::mt19937 gen(seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (double v : run.result.history.watched_v) m.value.push_back(v + sigma * noise(gen));
    return m;
}

// Starts 30 %, 50 % and 40 % off: Kc 1000 -> 1300 N/m, zeta_c 0.2 -> 0.3, zeta_1 0.005 -> 0.007.
std::vector<FitParameter> three_parameters(Case& start) {
    start.supports[0].stiffness = 1300.0;
    start.supports[0].damping_ratio = 0.3;
    start.damping.ratio1 = 0.007;
    return {parse_fit_parameter("supports[0].stiffness", start), parse_fit_parameter("supports[0].damping_ratio", start),
            parse_fit_parameter("damping.ratios[0]", start)};
}

const double kTruth[3] = {1000.0, 0.2, 0.005};

TEST(Fit, RecoversKcZetaCAndADampingRatioFromANoisyTipTrajectory) {
    const Case truth = truth_case();
    const MeasuredTrajectory data = synthetic(truth, 2e-9, 20261125u);  // 0.2 % of the 1 um swing
    Case start = truth;
    const std::vector<FitParameter> params = three_parameters(start);
    const FitResult r = fit_trajectory(start, params, data);
    ASSERT_TRUE(r.converged) << r.message;
    std::printf("fit: %d iterations, %d simulations, rms residual %.3g m (noise 2e-9 m)\n", r.iterations, r.simulations, r.rms);
    for (std::size_t i = 0; i < 3; ++i) {
        std::printf("  %s: %.6g +- %.3g (95 %%: %.6g .. %.6g), truth %.6g, z = %.2f\n", params[i].path.text().c_str(),
                    r.estimate[i], r.std_error[i], r.ci_low[i], r.ci_high[i], kTruth[i], (r.estimate[i] - kTruth[i]) / r.std_error[i]);
        EXPECT_TRUE(r.undetermined[i].empty()) << r.undetermined[i];
        EXPECT_LE(r.ci_low[i], kTruth[i]) << params[i].path.text();
        EXPECT_GE(r.ci_high[i], kTruth[i]) << params[i].path.text();
    }
    // The residual is the noise: its rms within 10 % of sigma.
    EXPECT_NEAR(r.rms, 2e-9, 2e-10);
    EXPECT_NEAR(r.sigma, 2e-9, 2e-10);
}

// Without noise the fit returns the truth (to the simulation's own accuracy); with the noise
// divided by 4 the intervals shrink by 4 (the linear regime: std errors scale with sigma).
TEST(Fit, NoiseFreeDataGiveTheTruthAndIntervalsScaleWithTheNoise) {
    const Case truth = truth_case();
    Case start = truth;
    const std::vector<FitParameter> params = three_parameters(start);
    const FitResult exact = fit_trajectory(start, params, synthetic(truth, 0.0, 1u));
    ASSERT_TRUE(exact.converged) << exact.message;
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(exact.estimate[i] / kTruth[i], 1.0, 1e-7) << params[i].path.text();
    const FitResult wide = fit_trajectory(start, params, synthetic(truth, 4e-9, 7u));
    const FitResult narrow = fit_trajectory(start, params, synthetic(truth, 1e-9, 7u));
    for (std::size_t i = 0; i < 3; ++i) {
        const double ratio = wide.std_error[i] / narrow.std_error[i];
        std::printf("  %s: std error %.3g at sigma 4e-9, %.3g at 1e-9: ratio %.3f\n", params[i].path.text().c_str(),
                    wide.std_error[i], narrow.std_error[i], ratio);
        EXPECT_NEAR(ratio, 4.0, 0.2) << params[i].path.text();
    }
}

// With plate_modulus the beam's stiffness is E / (1 - nu^2): E and nu trade off exactly, and the
// fit must say so rather than give confident numbers.
TEST(Fit, TwoParametersThatTradeOffAreReportedAsUndetermined) {
    Case truth = truth_case();
    truth.material.plate_modulus = true;
    const MeasuredTrajectory data = synthetic(truth, 2e-9, 3u);
    Case start = truth;
    start.material.youngs_modulus = 1.1 * truth.material.youngs_modulus;
    const std::vector<FitParameter> params = {parse_fit_parameter("material.youngs_modulus=150e9:300e9", start),
                                              parse_fit_parameter("material.poisson_ratio=0.1:0.45", start)};
    const FitResult r = fit_trajectory(start, params, data);
    for (std::size_t i = 0; i < 2; ++i) {
        std::printf("  %s: %.6g, %s\n", params[i].path.text().c_str(), r.estimate[i],
                    r.undetermined[i].empty() ? "determined" : r.undetermined[i].c_str());
        EXPECT_NE(r.undetermined[i].find("trades off with"), std::string::npos) << params[i].path.text();
        EXPECT_TRUE(std::isnan(r.std_error[i]));
    }
    // What the data do fix: E / (1 - nu^2) of the truth.
    const double plate = r.estimate[0] / (1.0 - r.estimate[1] * r.estimate[1]);
    const double truth_plate = truth.material.youngs_modulus / (1.0 - truth.material.poisson_ratio * truth.material.poisson_ratio);
    EXPECT_NEAR(plate / truth_plate, 1.0, 1e-3);
}

TEST(Fit, BadDataFilesAndSettingsAreInputErrorsNamingTheLine) {
    const std::string dir = test::make_temp_dir();
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir + "/" + name) << text;
        return dir + "/" + name;
    };
    const std::string bad_time = write("t.csv", "t_s,tip_m\n0,1e-6\n1e-8,0.9e-6\n1e-8,0.8e-6\n3e-8,0.7e-6\n");
    const std::string bad_nan = write("n.csv", "t_s,tip_m\n0,1e-6\n1e-8,nan\n");
    const std::string no_column = write("c.csv", "t_s,x\n0,1\n");
    const std::string too_few = write("f.csv", "t_s,tip_m\n0,1e-6\n1e-8,1e-6\n");
    const std::string bad_sigma = write("s.csv", "t_s,tip_m,sigma\n0,1e-6,0\n1e-8,1e-6,1e-9\n");
    const auto message = [](const std::string& path, std::size_t rows) {
        try {
            (void)read_measured_trajectory(path, "tip_m", rows);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(bad_time, 3).find("t.csv:4: t_s: times must increase"), std::string::npos) << message(bad_time, 3);
    EXPECT_NE(message(bad_nan, 1).find("n.csv:3: tip_m"), std::string::npos) << message(bad_nan, 1);
    EXPECT_NE(message(no_column, 1).find("c.csv:1: the header row must name"), std::string::npos) << message(no_column, 1);
    EXPECT_NE(message(too_few, 4).find("fewer than the 4 needed"), std::string::npos) << message(too_few, 4);
    EXPECT_NE(message(bad_sigma, 1).find("s.csv:2: sigma"), std::string::npos) << message(bad_sigma, 1);

    const Case c = truth_case();
    for (const char* bad : {"supports[0].stiffness=2000:100", "supports[0].stiffness=10:100", "beam.elements",
                            "supports[0].gap", "nosuch.key", "supports[0].stiffness=a:b"}) {
        EXPECT_THROW(parse_fit_parameter(bad, c), InputError) << bad;
    }
    // Through the command: exit 2, one line, nothing written.
    const auto r = test::run_vibroimpact({"fit", test::source_path("examples/paper/free_impact_tip.toml"), "--data", bad_time,
                                          "--fit", "supports[0].stiffness", "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
