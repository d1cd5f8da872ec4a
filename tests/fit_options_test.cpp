// `vibroimpact fit` on a trajectory with its options (calibration/trajectory_fit): the time shift
// and scale of the record as nuisance parameters, several starts, the two-stage fit, and the watched
// point's column named for the case.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "calibration/trajectory_fit.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace {

// The paper's free-impact case over 40 us, sampled every 40 ns (1001 samples, 7 impacts).
Case truth_case() {
    Case c = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    c.solver.horizon = 40e-6;
    c.solver.output_step = 40e-9;
    return c;
}

// g * y(t - shift_samples * 40 ns) + noise at t = k * 40 ns, from the truth's own history: the
// shift is a whole number of samples, so the data need no interpolation (y(t < 0) = y(0), the
// beam held before its release).
MeasuredTrajectory shifted(const Case& truth, int shift_samples, double g, double sigma, unsigned seed) {
    SimulationOptions o;
    o.energy = false;
    const SimulationRun run = run_simulation(truth, o);
    const std::vector<double>& y = run.result.history.watched_v;
    MeasuredTrajectory m;
    m.file = "synthetic";
    m.column = "tip_m";
    m.t = run.result.history.t;
    std::mt19937 gen(seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (std::size_t k = 0; k < m.t.size(); ++k) {
        const long from = static_cast<long>(k) - shift_samples;
        m.value.push_back(g * y[static_cast<std::size_t>(std::max(0L, from))] + sigma * noise(gen));
    }
    return m;
}

void print(const std::vector<FitParameter>& params, const FitResult& r) {
    for (std::size_t i = 0; i < params.size(); ++i) {
        std::printf("  %s: %.6g +- %.3g (95 %%: %.6g .. %.6g)%s\n", params[i].name().c_str(), r.estimate[i], r.std_error[i],
                    r.ci_low[i], r.ci_high[i], r.undetermined[i].empty() ? "" : (" " + r.undetermined[i]).c_str());
    }
}

void expect_inside(const FitResult& r, std::size_t i, double truth, const std::string& name) {
    EXPECT_LE(r.ci_low[i], truth) << name;
    EXPECT_GE(r.ci_high[i], truth) << name;
}

// Data 0.4 us late (10 samples) and 5 % high: the fit finds t0 and g with Kc and zeta_c.
TEST(FitOptions, TimeShiftAndScaleAreRecoveredAsNuisanceParameters) {
    const Case truth = truth_case();
    const MeasuredTrajectory data = shifted(truth, 10, 1.05, 2e-9, 42u);
    Case start = truth;
    start.supports[0].stiffness = 1300.0;
    start.supports[0].damping_ratio = 0.3;
    std::vector<FitParameter> params = {parse_fit_parameter("supports[0].stiffness", start),
                                        parse_fit_parameter("supports[0].damping_ratio", start),
                                        time_shift_parameter(data.t.back() - data.t.front()), scale_parameter()};
    const FitResult r = fit_trajectory(start, params, data);
    ASSERT_TRUE(r.converged) << r.message;
    std::printf("fit: %d iterations, %d simulations, rms %.3g\n", r.iterations, r.simulations, r.rms);
    print(params, r);
    expect_inside(r, 0, 1000.0, "Kc");
    expect_inside(r, 1, 0.2, "zeta_c");
    expect_inside(r, 2, 0.4e-6, "t0");
    expect_inside(r, 3, 1.05, "g");
    EXPECT_NEAR(r.rms, 2e-9, 2e-10);
}

// A record 3 us late (75 samples): from Kc = 1200 N/m, t0 = 0 the fit stops in a local minimum (Kc
// near 7000 N/m, a cost some 2000 times the global one: measured); the third start of a Halton
// sample of the bounds (316 N/m, +1.3 us) reaches the global one. Which minimum one start reaches
// depends on the last bits of the simulations (measured: from 1100, 1200, 1240, 1250, 1280 and 5000
// N/m the fit stops between 4200 and 6900 N/m, from 1150, 1220, 1300 and 3000 N/m at the truth; the
// case's own 1300 N/m stopped locally before the signal scans' exponentials changed their rounding).
TEST(FitOptions, SeveralStartsFindTheGlobalMinimumWhereOneStartStopsInALocalOne) {
    const Case truth = truth_case();
    const MeasuredTrajectory data = shifted(truth, 75, 1.0, 2e-9, 9u);
    Case start = truth;
    start.supports[0].stiffness = 1200.0;
    std::vector<FitParameter> params = {parse_fit_parameter("supports[0].stiffness=100:10000", start),
                                        time_shift_parameter(data.t.back() - data.t.front())};
    FitOptions several;
    several.starts = 3;
    several.threads = 2;
    const FitResult multi = fit_trajectory(start, params, data, several);
    std::printf("3 starts: best %zu, cost %.6g, %d distinct minima\n", multi.best + 1, multi.cost, multi.distinct_minima);
    for (const StartRun& s : multi.starts) {
        std::printf("  start (%.5g, %.5g) -> (%.6g, %.6g), cost %.6g, converged %d, minimum %d, %d simulations\n",
                    s.start[0], s.start[1], s.end[0], s.end[1], s.cost, s.converged, s.minimum, s.simulations);
    }
    print(params, multi);
    expect_inside(multi, 0, 1000.0, "Kc");
    expect_inside(multi, 1, 3e-6, "t0");
    // The first start alone (what --starts 1 runs) converged, far from the truth, at a worse cost.
    const StartRun& first = multi.starts[0];
    EXPECT_TRUE(first.converged);
    EXPECT_GT(std::abs(first.end[0] - 1000.0), 100.0 * multi.std_error[0]);
    EXPECT_GT(first.cost, 100.0 * multi.cost);
    EXPECT_NE(multi.best, 0u);
    EXPECT_GT(multi.distinct_minima, 1);
    EXPECT_NE(first.minimum, 0);
}

// The two-stage fit of the recovery case (Kc, zeta_c, zeta_1; 55 samples before the first impact):
// zeta_1 from the fall before the first impact, then Kc and zeta_c with it fixed. Stage 2's own
// intervals, taking zeta_1 as exact, miss the one-stage zeta_c (measured: 0.20117 +- 0.00012
// against 0.19953); with stage 1's uncertainty carried over, both stages hold the one-stage
// estimates and the truth.
TEST(FitOptions, TwoStageFitAgreesWithTheOneStageFitWithinTheIntervals) {
    Case truth = truth_case();
    const MeasuredTrajectory data = shifted(truth, 0, 1.0, 2e-9, 20261125u);
    Case start = truth;
    start.supports[0].stiffness = 1300.0;
    start.supports[0].damping_ratio = 0.3;
    start.damping.ratio1 = 0.007;
    const std::vector<FitParameter> params = {parse_fit_parameter("supports[0].stiffness", start),
                                              parse_fit_parameter("supports[0].damping_ratio", start),
                                              parse_fit_parameter("damping.ratios[0]", start)};
    const FitResult one = fit_trajectory(start, params, data);
    const TwoStageFit two = fit_two_stage(start, params, data);
    ASSERT_TRUE(two.stage1.converged && two.stage2.converged);
    std::printf("split at %.4g us, %zu samples before\n", two.split_time * 1e6, two.split_samples);
    std::printf("one stage:\n");
    print(params, one);
    std::printf("stage 1:\n");
    print({params[2]}, two.stage1);
    std::printf("stage 2 (std errors given stage 1: %.3g, %.3g):\n", two.stage2_conditional_std_error[0],
                two.stage2_conditional_std_error[1]);
    print({params[0], params[1]}, two.stage2);
    ASSERT_EQ(two.stage1_params, std::vector<std::size_t>{2});
    ASSERT_EQ(two.stage2_params, (std::vector<std::size_t>{0, 1}));
    const double truth_values[3] = {1000.0, 0.2, 0.005};
    expect_inside(two.stage1, 0, one.estimate[2], "zeta_1 (one stage)");
    expect_inside(two.stage1, 0, truth_values[2], "zeta_1");
    for (std::size_t a = 0; a < 2; ++a) {
        expect_inside(two.stage2, a, one.estimate[a], params[a].name() + " (one stage)");
        expect_inside(two.stage2, a, truth_values[a], params[a].name());
        EXPECT_GT(two.stage2.std_error[a], two.stage2_conditional_std_error[a]);
    }
}

// Either stage without a parameter is refused.
TEST(FitOptions, TwoStageWithoutParametersForAStageIsRefused) {
    const Case c = truth_case();
    const MeasuredTrajectory data = shifted(c, 0, 1.0, 0.0, 1u);
    try {
        (void)fit_two_stage(c, {parse_fit_parameter("supports[0].stiffness", c)}, data);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--two-stage: stage 1 (the record before the first impact) has no parameter"),
                  std::string::npos) << e.what();
    }
    try {
        (void)fit_two_stage(c, {parse_fit_parameter("damping.ratios[0]", c)}, data);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--two-stage: stage 2 (the impacts) has no parameter"), std::string::npos)
            << e.what();
    }
}

// The data column is the case's watched point: tip_m at a free end, midspan_m on a beam held at
// both ends; the other is refused naming the right one.
TEST(FitOptions, TheDataColumnIsTheCasesWatchedPoint) {
    const Case tip = truth_case();
    const Case bridge = read_case_file(test::source_path("examples/devices/bridge_relay.toml"));
    EXPECT_EQ(watched_point_name(tip), "tip");
    EXPECT_EQ(watched_point_name(bridge), "midspan");
    EXPECT_NO_THROW(check_trajectory_column(tip, "tip_m"));
    EXPECT_NO_THROW(check_trajectory_column(tip, "tip_velocity_m_s"));
    EXPECT_NO_THROW(check_trajectory_column(bridge, "midspan_m"));
    EXPECT_NO_THROW(check_trajectory_column(bridge, "midspan_velocity_m_s"));
    try {
        check_trajectory_column(bridge, "tip_m");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--column tip_m: this case's watched point is the mid-span"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("midspan_m and midspan_velocity_m_s"), std::string::npos) << e.what();
    }
    const auto r = test::run_vibroimpact({"fit", test::source_path("examples/paper/free_impact_tip.toml"), "--data",
                                          "no-such.csv", "--column", "midspan_m", "--fit", "supports[0].stiffness",
                                          "--out", test::make_temp_dir() + "/out"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--column midspan_m: this case's watched point is the free end (tip): its columns are tip_m"),
              std::string::npos) << r.err;
}

}  // namespace
}  // namespace vi
