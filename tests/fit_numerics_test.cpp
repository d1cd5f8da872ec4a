// `vibroimpact fit` when the numbers go wrong: data outside the magnitudes double precision computes
// with are refused naming the line, a misfit that overflows is refused at the start, a Jacobian that
// underflows or residuals that are not finite give undetermined parameters (never a zero interval),
// settings the fit derives from the data are blamed on the data, and the least-squares library's
// log stays off stderr.

#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "calibration/least_squares.hpp"
#include "calibration/trajectory_fit.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "io/number_text.hpp"
#include "model/input_error.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

std::string example_case() { return test::source_path("examples/paper/free_impact_tip.toml"); }

// The example over 10 us, sampled every 100 ns (101 samples, two impacts), as the data of a fit.
MeasuredTrajectory ten_microseconds() {
    Case c = read_case_file(example_case());
    c.solver.horizon = 10e-6;
    c.solver.output_step = 100e-9;
    SimulationOptions o;
    o.energy = false;
    const SimulationRun run = run_simulation(c, o);
    MeasuredTrajectory m;
    m.file = "synthetic";
    m.column = "tip_m";
    m.t = run.result.history.t;
    m.value = run.result.history.tip_v;
    return m;
}

// The trajectory as a data file; `cell` may replace sample k's tip_m or sigma text.
std::string data_file(const std::string& dir, const std::string& name, const MeasuredTrajectory& m,
                      const std::function<void(std::size_t, std::string&, std::string&)>& cell = {}, bool sigma = false) {
    std::string text = sigma ? "t_s,tip_m,sigma\n" : "t_s,tip_m\n";
    for (std::size_t k = 0; k < m.t.size(); ++k) {
        std::string value = round_trip_text(m.value[k]), s = "2e-9";
        if (cell) cell(k, value, s);
        text += round_trip_text(m.t[k]) + "," + value + (sigma ? "," + s : "") + "\n";
    }
    test::write_text(dir + "/" + name, text);
    return dir + "/" + name;
}

test::CommandResult fit(const std::string& data, const std::string& out, std::vector<std::string> more = {}) {
    std::vector<std::string> args{"fit", example_case(), "--data", data, "--out", out};
    if (more.empty()) more = {"--fit", "supports[0].stiffness"};
    args.insert(args.end(), more.begin(), more.end());
    return test::run_vibroimpact(args);
}

std::size_t stderr_line_count(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

TEST(FitNumerics, DataOutsideTheMagnitudeWindowAreExit2NamingFileLineAndColumn) {
    const std::string dir = test::make_temp_dir();
    const MeasuredTrajectory m = ten_microseconds();
    struct Bad {
        std::string name, expected;
        std::function<void(std::size_t, std::string&, std::string&)> cell;
        bool sigma;
    };
    // Sample 5 is on line 7 (the header is line 1).
    const std::vector<Bad> bad = {
        {"huge.csv", "huge.csv:7: tip_m: 1e308 is outside", [](std::size_t k, std::string& v, std::string&) { if (k == 5) v = "1e308"; }, false},
        {"tiny.csv", "tiny.csv:7: tip_m: 1e-320 is outside", [](std::size_t k, std::string& v, std::string&) { if (k == 5) v = "1e-320"; }, false},
        {"sigma_huge.csv", "sigma_huge.csv:2: sigma: 1e300 is outside", [](std::size_t, std::string&, std::string& s) { s = "1e300"; }, true},
        {"sigma_tiny.csv", "sigma_tiny.csv:2: sigma: 1e-320 is outside", [](std::size_t, std::string&, std::string& s) { s = "1e-320"; }, true},
    };
    for (const Bad& b : bad) {
        const std::string out = dir + "/out_" + b.name;
        const auto r = fit(data_file(dir, b.name, m, b.cell, b.sigma), out);
        EXPECT_EQ(r.exit_code, 2) << b.name << ": " << r.out << r.err;
        EXPECT_NE(r.err.find(b.expected), std::string::npos) << r.err;
        EXPECT_EQ(stderr_line_count(r.err), 1u) << r.err;
        EXPECT_FALSE(fs::exists(out)) << b.name;
    }
    // A feature's value or sigma likewise.
    test::write_text(dir + "/f.csv", "name,value,sigma\nT_s,5.4e-6,1e-7\nq1,1e300,3\n");
    const auto r = test::run_vibroimpact({"fit", example_case(), "--features", dir + "/f.csv", "--fit", "damping.ratios[0]",
                                          "--out", dir + "/out_f"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("f.csv:3: q1: value 1e300 is outside"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out_f"));
    fs::remove_all(dir);
}

TEST(FitNumerics, AMisfitWhoseSquaresOverflowIsExit2NamingTheSample) {
    const std::string dir = test::make_temp_dir();
    // Both within the window, but (model - data) / sigma = 1e180 squares past 1e308.
    const std::string data = data_file(
        dir, "o.csv", ten_microseconds(),
        [](std::size_t k, std::string& v, std::string& s) {
            s = "1e-90";
            if (k == 7) v = "1e90";
        },
        true);
    const auto r = fit(data, dir + "/out");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("o.csv:9: sigma: (model - data) / sigma = -1e+180 at the start values"), std::string::npos) << r.err;
    EXPECT_EQ(stderr_line_count(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
    fs::remove_all(dir);
}

// A parameter never comes with a standard error of zero or one that is not a number while it is
// called determined: either it is undetermined (NaN, with a reason) or its error is finite and > 0.
void expect_honest(const FitResult& r, const std::vector<FitParameter>& params) {
    for (std::size_t i = 0; i < params.size(); ++i) {
        if (r.undetermined[i].empty()) {
            EXPECT_TRUE(std::isfinite(r.std_error[i]) && r.std_error[i] > 0.0) << params[i].name() << ": " << r.std_error[i];
        } else {
            EXPECT_TRUE(std::isnan(r.std_error[i])) << params[i].name();
            EXPECT_TRUE(std::isnan(r.ci_low[i]) && std::isnan(r.ci_high[i])) << params[i].name();
        }
    }
}

TEST(FitNumerics, AJacobianThatUnderflowsGivesUndeterminedParametersNeverAZeroInterval) {
    const Case c = read_case_file(example_case());
    const std::vector<FitParameter> params{parse_fit_parameter("supports[0].stiffness", c)};
    // Residuals 1e-200 (x - 1000) / 700: J^T J = 1e-400 rounds to zero.
    LeastSquaresProblem p;
    p.params = params;
    p.residuals = 20;
    p.sigma_known = true;
    p.evaluate = [](const std::vector<double>& x, double* r) {
        for (int k = 0; k < 20; ++k) r[k] = 1e-200 * (x[0] - 1000.0 - k) / 700.0;
    };
    for (const bool known : {true, false}) {
        p.sigma_known = known;
        const FitResult r = fit_least_squares(p, {});
        ASSERT_EQ(r.undetermined.size(), 1u);
        EXPECT_FALSE(r.undetermined[0].empty()) << "std error " << r.std_error[0];
        expect_honest(r, params);
    }

    // The original report: one sample of 1e308 in a trajectory made in code (the file reader
    // refuses it; the library must still not call the start a perfect estimate).
    MeasuredTrajectory m = ten_microseconds();
    m.value[5] = 1e308;
    Case start = c;
    start.supports[0].stiffness = 700.0;
    const std::vector<FitParameter> kc{parse_fit_parameter("supports[0].stiffness", start)};
    const FitResult r = fit_trajectory(start, kc, m);
    std::printf("one sample of 1e308: estimate %.6g, std error %.3g, undetermined '%s', converged %d\n", r.estimate[0],
                r.std_error[0], r.undetermined[0].c_str(), r.converged ? 1 : 0);
    EXPECT_FALSE(r.undetermined[0].empty());
    expect_honest(r, kc);
}

TEST(FitNumerics, ResidualsThatAreNotFiniteAtEveryStartAreAnErrorNotAResult) {
    const Case c = read_case_file(example_case());
    LeastSquaresProblem p;
    p.params = {parse_fit_parameter("supports[0].stiffness", c)};
    p.residuals = 3;
    p.evaluate = [](const std::vector<double>& x, double* r) {
        for (int k = 0; k < 3; ++k) r[k] = 1e300 * x[0];  // its square overflows: an infinite cost
    };
    EXPECT_THROW((void)fit_least_squares(p, {}), std::runtime_error);
    p.evaluate = [](const std::vector<double>&, double* r) {
        for (int k = 0; k < 3; ++k) r[k] = std::nan("");
    };
    EXPECT_THROW((void)fit_least_squares(p, {}), std::runtime_error);
}

TEST(FitNumerics, AHorizonTheFitDerivesFromTheDataIsBlamedOnTheDataFile) {
    const std::string dir = test::make_temp_dir();
    // Two samples 10 ns apart: the model's horizon, 10 ns, sees no impact.
    test::write_text(dir + "/two.csv", "t_s,tip_m\n0,1e-6\n1e-8,0.9997e-6\n");
    const auto r = fit(dir + "/two.csv", dir + "/out");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("two.csv:3: t_s: the record's last time, 1e-08 s, makes the model's horizon 1e-08 s: too short"),
              std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(".toml"), std::string::npos) << r.err;
    EXPECT_EQ(stderr_line_count(r.err), 1u) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
    fs::remove_all(dir);
}

TEST(FitNumerics, TheLeastSquaresLibraryWritesNothingOnStderr) {
    const std::string dir = test::make_temp_dir();
    const std::string data = data_file(dir, "tip.csv", ten_microseconds());
    // Five starts over 10 .. 1e10 N/m: the fifth (133 N/m) cannot take its first difference step
    // (the case refuses a negative stiffness) and fails, the others converge. Ceres logged that
    // failure to stderr through glog ("Logging before InitGoogleLogging() ...", "Terminating: ...").
    const auto ok = fit(data, dir + "/ok", {"--fit", "supports[0].stiffness=10:1e10", "--starts", "5"});
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_NE(ok.out.find("5  inf"), std::string::npos) << ok.out;  // the failed start is in the table
    EXPECT_EQ(ok.err, "");
    // A fit that fails at every start: one line of its own.
    const auto bad = fit(data, dir + "/bad", {"--fit", "supports[0].stiffness=100:1e12", "--starts", "4"});
    EXPECT_EQ(bad.exit_code, 1) << bad.err;
    EXPECT_EQ(stderr_line_count(bad.err), 1u) << bad.err;
    EXPECT_EQ(bad.err.rfind("vibroimpact: fit: did not converge", 0), 0u) << bad.err;
    EXPECT_EQ(bad.err.find("InitGoogleLogging"), std::string::npos) << bad.err;
    fs::remove_all(dir);
}

TEST(FitNumerics, AFitStoppedBySigintSaysOnlyThat) {
    const std::string dir = test::make_temp_dir();
    const std::string data = data_file(dir, "tip.csv", ten_microseconds());
    // Forty starts on two threads: seconds of work, stopped half a second in (the residuals then
    // refuse to run, which Ceres logged as "Terminating: Residual and Jacobian evaluation failed").
    test::ChildProcess child({test::vibroimpact_path(), "fit", example_case(), "--data", data, "--fit",
                              "supports[0].stiffness=100:10000", "--fit", "supports[0].damping_ratio=0.05:0.5", "--starts",
                              "40", "--threads", "2", "--out", dir + "/out"});
    test::wait_until([&] { return child.seconds() > 0.5; }, 10.0);
    ASSERT_TRUE(child.running()) << "the fit ended before the signal";
    child.signal(SIGINT);
    const auto r = child.wait();
    EXPECT_EQ(r.exit_code, 130) << r.err;
    EXPECT_EQ(r.err, "vibroimpact: stopped by SIGINT; nothing written\n");
    EXPECT_FALSE(fs::exists(dir + "/out"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
