// Wall time of the default free-impact transient (examples/paper/free_impact_tip.toml, m = 50)
// through T_p, for the exact solver (with its time split) and the nonlinear path (full and reduced
// order, with their error against the exact solver); and the
// exact transient over the example's whole horizon (150 us) with the support moved inside the beam,
// as a support-position sweep runs it; and the same impact on a Hertz dimple (CVODE, full and reduced);
// 100 actuation cycles of the Hertz-dimple switch.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "impacts/simulation.hpp"
#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/exact/exact_solver.hpp"
#include "io/case_reader.hpp"
#include "study/cycles/cycles.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

// The example with its horizon cut to its own T_p (found once by a full run).
vi::Case example_through_tp() {
    static const vi::Case c = [] {
        vi::Case k = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
        vi::SimulationOptions o;
        o.history = false;
        o.energy = false;
        const vi::SimulationRun run = vi::run_simulation(k, o);
        if (run.summary.Tp) k.solver.horizon = *run.summary.Tp;
        std::printf("example: T_p = %.4f us (%s), %zu episodes\n", k.solver.horizon * 1e6,
                    run.summary.Tp_reason.c_str(), run.result.episodes.size());
        return k;
    }();
    return c;
}

void report(benchmark::State& state, const vi::TransientResult& r) {
    state.counters["decomposition_ms"] = r.stats.decomposition_s * 1e3;
    state.counters["propagation_ms"] = r.stats.propagation_s * 1e3;
    state.counters["event_location_ms"] = r.stats.event_location_s * 1e3;
    state.counters["episodes"] = static_cast<double>(r.episodes.size());
    state.counters["states"] = r.stats.decompositions;
}

// Exact solver through T_p: events, episode peaks and extremes (y_max); with range(0) = 1 also the
// 10 ns history of the tip and contact (no energy ledger), with 2 the history and the energy ledger.
void BM_ExactThroughTp(benchmark::State& state) {
    const vi::Case c = example_through_tp();
    const vi::BuiltProblem b = vi::build_transient_problem(c);
    vi::TransientOptions o;
    o.history = state.range(0) >= 1;
    o.energy = state.range(0) >= 2;
    vi::TransientResult r;
    for (auto _ : state) {
        r = vi::solve_exact(b.problem, o);
        benchmark::DoNotOptimize(r.episodes.data());
    }
    report(state, r);
}
BENCHMARK(BM_ExactThroughTp)->Arg(0)->Arg(1)->Arg(2)->ArgName("history")->Unit(benchmark::kMillisecond);

// Exact solver, support at x/l = range(0) / 100, range(1) elements, the example's 150 us horizon,
// events, peaks and extremes only (as a sweep over support positions needs them).
void BM_ExactSupportAt(benchmark::State& state) {
    vi::Case c = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    c.supports.at(0).position = static_cast<double>(state.range(0)) / 100.0;
    c.beam.elements = static_cast<int>(state.range(1));
    const vi::BuiltProblem b = vi::build_transient_problem(c);
    vi::TransientOptions o;
    o.history = false;
    o.energy = false;
    vi::TransientResult r;
    for (auto _ : state) {
        r = vi::solve_exact(b.problem, o);
        benchmark::DoNotOptimize(r.episodes.data());
    }
    report(state, r);
}
BENCHMARK(BM_ExactSupportAt)
    ->Args({67, 50})
    ->Args({87, 50})
    ->Args({67, 10})
    ->Args({87, 10})
    ->ArgNames({"x_percent", "elements"})
    ->Unit(benchmark::kMillisecond);

// The nonlinear path (CVODE in modal coordinates) on the same transient at rtol = range(0) decades
// below 1 (8: 1e-8), with range(1) reduced modes (0: the full model), and its largest relative error
// against the exact solver in T, T2, y_max and the first impact's peak force (counter "error").
void BM_CvodeThroughTp(benchmark::State& state) {
    vi::Case c = example_through_tp();
    vi::SimulationOptions o;
    o.history = false;
    o.energy = false;
    const vi::SimulationRun exact = vi::run_simulation(c, o);
    c.solver.method = vi::SolverSettings::Method::cvode;
    c.solver.rtol = std::pow(10.0, -static_cast<double>(state.range(0)));
    c.solver.reduced_modes = static_cast<int>(state.range(1));
    const vi::BuiltProblem b = vi::build_transient_problem(c);
    vi::CvodeOptions co;
    co.rtol = c.solver.rtol;
    co.reduced_modes = c.solver.reduced_modes;
    vi::TransientResult r;
    for (auto _ : state) {
        r = vi::solve_cvode(b.problem, {}, co);
        benchmark::DoNotOptimize(r.episodes.data());
    }
    report(state, r);
    const vi::SimulationRun run = vi::run_simulation(c, o);
    const auto rel = [](double a, double x) { return std::abs(a / x - 1.0); };
    state.counters["error"] = std::max({rel(*run.summary.T_first, *exact.summary.T_first),
                                        rel(*run.summary.T2_first, *exact.summary.T2_first),
                                        rel(*run.summary.y_max, *exact.summary.y_max),
                                        rel(run.summary.impacts.front().peak_force, exact.summary.impacts.front().peak_force)});
    state.counters["steps"] = r.stats.steps;
    state.counters["basis"] = r.stats.basis_vectors;
}
BENCHMARK(BM_CvodeThroughTp)
    ->Args({8, 0})
    ->Args({10, 0})
    ->Args({6, 0})
    ->Args({8, 10})
    ->Args({6, 10})
    ->Args({8, 5})
    ->ArgNames({"rtol_exp", "reduced_modes"})
    ->Unit(benchmark::kMillisecond);

// The same free impact on a Hertz dimple (bench/cases/free_impact_hertz.toml, CVODE, 80 us: through
// the full model's T_p of 74.9 us), as `simulate` runs it (history and energy ledger on), with
// range(0) reduced modes (0: the full model); counter "Tp_us" is each model's own T_p.
void BM_HertzFreeImpact(benchmark::State& state) {
    vi::Case c = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/bench/cases/free_impact_hertz.toml");
    c.solver.reduced_modes = static_cast<int>(state.range(0));
    vi::SimulationRun run;
    for (auto _ : state) {
        run = vi::run_simulation(c, vi::SimulationOptions{});
        benchmark::DoNotOptimize(run.result.episodes.data());
    }
    state.counters["episodes"] = static_cast<double>(run.result.episodes.size());
    state.counters["steps"] = run.result.stats.steps;
    state.counters["Tp_us"] = run.summary.Tp ? *run.summary.Tp * 1e6 : 0.0;
}
BENCHMARK(BM_HertzFreeImpact)->Arg(0)->Arg(10)->ArgName("reduced_modes")->Unit(benchmark::kMillisecond);

// Building the problem (modes, static step) is part of every run of a sweep.
void BM_BuildProblem(benchmark::State& state) {
    const vi::Case c = example_through_tp();
    for (auto _ : state) {
        vi::BuiltProblem b = vi::build_transient_problem(c);
        benchmark::DoNotOptimize(b.problem.q0.data());
    }
}
BENCHMARK(BM_BuildProblem)->Unit(benchmark::kMillisecond);

// The cycles study of the Hertz-dimple switch (examples/switch/cantilever_switch_hertz_cycles.toml:
// a 70 V pulse every 100 us, reduced model of 10 modes) over range(0) cycles, as `cycles` runs it.
void BM_HertzSwitchCycles(benchmark::State& state) {
    const vi::Case c =
        vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch_hertz_cycles.toml");
    vi::CyclesResult r;
    for (auto _ : state) {
        r = vi::run_cycles(c, {static_cast<int>(state.range(0)), 0.0});
        benchmark::DoNotOptimize(r.cycles.data());
    }
    state.counters["steps"] = r.steps;
    state.counters["last_bounces"] = r.bounce_trend.last;
    state.counters["energy_J"] = r.total_contact_energy;
}
BENCHMARK(BM_HertzSwitchCycles)->Arg(100)->ArgName("cycles")->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
