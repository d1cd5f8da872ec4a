// Wall time of calibration and design optimisation on the paper's free-impact case
// (examples/paper/free_impact_tip.toml): a fit of Kc, zeta_c and zeta_1 to a noisy 150 us tip
// trajectory (3751 samples every 40 ns) from starts 30-50 % off (one start; four starts on one
// thread and on every CPU), and `optimize` of z_max over the support position and the contact
// stiffness (80 evaluations) on 1 and 2 threads.

#include <benchmark/benchmark.h>

#include <random>
#include <string>

#include "calibration/trajectory_fit.hpp"
#include "design/optimizer.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

vi::Case paper_case() { return vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml"); }

// The fit of Kc, zeta_c and zeta_1 to a 150 us trajectory from state.range(0) starts on
// state.range(1) threads (0: every CPU the process may use).
void BM_FitThreeParameters(benchmark::State& state) {
    vi::Case truth = paper_case();
    truth.solver.output_step = 40e-9;  // 150 us horizon: 3751 samples
    vi::SimulationOptions so;
    so.energy = false;
    const vi::SimulationRun run = vi::run_simulation(truth, so);
    vi::MeasuredTrajectory data;
    data.file = "synthetic";
    data.column = "tip_m";
    data.t = run.result.history.t;
    std::mt19937 gen(1);
    std::normal_distribution<double> noise(0.0, 2e-9);
    for (double v : run.result.history.watched_v) data.value.push_back(v + noise(gen));
    vi::Case start = truth;
    start.supports[0].stiffness = 1300.0;
    start.supports[0].damping_ratio = 0.3;
    start.damping.ratio1 = 0.007;
    const std::vector<vi::FitParameter> params = {vi::parse_fit_parameter("supports[0].stiffness", start),
                                                  vi::parse_fit_parameter("supports[0].damping_ratio", start),
                                                  vi::parse_fit_parameter("damping.ratios[0]", start)};
    vi::FitResult r;
    vi::FitOptions o;
    o.starts = static_cast<int>(state.range(0));
    o.threads = static_cast<int>(state.range(1));
    for (auto _ : state) {
        r = vi::fit_trajectory(start, params, data, o);
        benchmark::DoNotOptimize(r.estimate.data());
    }
    state.counters["samples"] = static_cast<double>(data.t.size());
    state.counters["simulations"] = r.simulations;
    state.counters["iterations"] = r.iterations;
    state.counters["Kc"] = r.estimate[0];
    state.counters["distinct_minima"] = r.distinct_minima;
}
BENCHMARK(BM_FitThreeParameters)->Args({1, 1})->Args({4, 1})->Args({4, 0})->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void BM_OptimizeTwoVariables(benchmark::State& state) {
    vi::DesignProblem p;
    p.base = paper_case();
    p.columns = vi::sweep_result_columns(vi::SweepAnalysis::simulate, 0);
    p.variables = {vi::parse_design_variable("supports[0].position=0.3:1", p.base),
                   vi::parse_design_variable("supports[0].stiffness=100:10000", p.base)};
    p.objective = vi::quantity_column("z_max", p.columns, "--minimize");
    vi::OptimizeOptions o;
    o.max_evaluations = 80;
    o.threads = static_cast<int>(state.range(0));
    vi::OptimizeResult r;
    for (auto _ : state) {
        r = vi::optimize_design(p, o);
        benchmark::DoNotOptimize(r.evaluations.data());
    }
    state.counters["evaluations"] = static_cast<double>(r.evaluations.size());
    state.counters["z_max"] = r.best ? *r.evaluations[*r.best].outcome.objective : 0.0;
    state.counters["computed"] = static_cast<double>(r.computed);
    state.counters["rounds"] = static_cast<double>(r.batches);
    state.counters["look_ahead_ms"] = 1e3 * r.look_ahead_s;
}
// On 1 and 2 threads (the same search; the look-ahead computes designs ahead on the second).
BENCHMARK(BM_OptimizeTwoVariables)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

}  // namespace
