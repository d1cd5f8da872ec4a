// Wall time of the cantilever switch (examples/switch/cantilever_switch.toml, the paper's nickel
// beam over an electrode, a contact stop under the free end): the static pull-in trace for m = 50
// (and coarser and finer meshes), and the 50 us switching transient after a step to 1.2 V_PI on the
// full FE model and on reduced-order models, with the reduced models' error against the full one;
// and the stiction example's pulse transient with and without its adhesive contact.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "statics/pullin.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

vi::Case switch_case() {
    return vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch.toml");
}

// `vibroimpact pullin` on the example with range(0) elements: the branch through pull-in and
// touch-down, release, collapse, and (range(1) = 16, the command's default) the frequencies under
// bias at 16 voltages x 3 modes, or (0) none.
void BM_Pullin(benchmark::State& state) {
    vi::Case c = switch_case();
    c.beam.elements = static_cast<int>(state.range(0));
    vi::PullinOptions o;
    o.frequency_points = static_cast<int>(state.range(1));
    vi::PullinResult r;
    for (auto _ : state) {
        r = vi::trace_pullin(c, o);
        benchmark::DoNotOptimize(r.branch.data());
    }
    state.counters["V_PI"] = r.pullin ? r.pullin->voltage : 0.0;
    state.counters["points"] = static_cast<double>(r.branch.size());
    state.counters["newton"] = r.newton_iterations;
    state.counters["lu_fallbacks"] = r.lu_fallbacks;
}
BENCHMARK(BM_Pullin)
    ->Args({20, 16})
    ->Args({50, 16})
    ->Args({50, 0})
    ->Args({100, 16})
    ->ArgNames({"elements", "frequency_points"})->Unit(benchmark::kMillisecond);

// The example's voltage set to 1.2 V_PI (its own static pull-in voltage).
vi::Case switch_at_1_2_vpi() {
    static const vi::Case c = [] {
        vi::Case k = switch_case();
        const vi::PullinResult p = vi::trace_pullin(k);
        k.electrodes.at(0).voltage = 1.2 * p.pullin.value().voltage;
        std::printf("example: V_PI = %.4f V, step to %.4f V, horizon %.1f us\n", p.pullin->voltage,
                    k.electrodes[0].voltage, k.solver.horizon * 1e6);
        return k;
    }();
    return c;
}

vi::SimulationRun run(const vi::Case& c, int reduced_modes, double rtol) {
    vi::Case k = c;
    k.solver.reduced_modes = reduced_modes;
    k.solver.rtol = rtol;
    vi::SimulationOptions o;
    o.history = false;
    o.energy = false;
    return vi::run_simulation(k, o);
}

// The 50 us switching transient (CVODE, events and episode peaks, no history) with range(1)
// reduced modes (0: the full model) at rtol 10^-range(0). Counters: the first contact time, the
// episodes, and the largest relative error against the full model at rtol 1e-10 of the first
// contact time, the first impact's velocity and peak force, and the first impact's duration.
void BM_SwitchTransient(benchmark::State& state) {
    const vi::Case c = switch_at_1_2_vpi();
    static const vi::SimulationRun reference = run(c, 0, 1e-10);
    const int reduced = static_cast<int>(state.range(1));
    const double rtol = std::pow(10.0, -static_cast<double>(state.range(0)));
    vi::SimulationRun r;
    for (auto _ : state) {
        r = run(c, reduced, rtol);
        benchmark::DoNotOptimize(r.result.episodes.data());
    }
    const auto rel = [](double a, double x) { return std::abs(a / x - 1.0); };
    const vi::Impact& a = r.summary.impacts.at(0);
    const vi::Impact& x = reference.summary.impacts.at(0);
    state.counters["t_close_us"] = a.t_on * 1e6;
    state.counters["episodes"] = static_cast<double>(r.result.episodes.size());
    state.counters["error"] = std::max({rel(a.t_on, x.t_on), rel(a.v_in, x.v_in), rel(a.peak_force, x.peak_force),
                                        rel(a.t_off - a.t_on, x.t_off - x.t_on)});
    state.counters["steps"] = r.result.stats.steps;
    state.counters["basis"] = r.result.stats.basis_vectors;
}
BENCHMARK(BM_SwitchTransient)
    ->Args({8, 0})
    ->Args({6, 0})
    ->Args({8, 8})
    ->Args({6, 8})
    ->Args({6, 4})
    ->Args({6, 2})
    ->ArgNames({"rtol_exp", "reduced_modes"})
    ->Unit(benchmark::kMillisecond);

// The stiction example (examples/switch/cantilever_stiction.toml: the same switch, a 70 V pulse of
// 20 us, 60 us horizon, m = 50, rtol 1e-8) with its adhesive tip contact (range(0) = 1, w in J/m^2
// x 10 = range(1)) against the same case with a plain Kelvin-Voigt stop (range(0) = 0): what adhesion
// costs the nonlinear path. Counters: episodes, CVODE steps, 1 when stuck at the horizon.
void BM_StictionTransient(benchmark::State& state) {
    vi::Case c = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_stiction.toml");
    if (state.range(0) == 0) {
        c.supports.at(0).adhesion = vi::Adhesion::none;
    } else {
        c.supports.at(0).work_of_adhesion = 0.1 * static_cast<double>(state.range(1));
    }
    vi::SimulationRun r;
    for (auto _ : state) {
        r = run(c, 0, c.solver.rtol);
        benchmark::DoNotOptimize(r.result.episodes.data());
    }
    state.counters["episodes"] = static_cast<double>(r.result.episodes.size());
    state.counters["steps"] = r.result.stats.steps;
    state.counters["stuck"] = r.switching && r.switching->state == "stuck" ? 1.0 : 0.0;
}
BENCHMARK(BM_StictionTransient)
    ->Args({0, 0})
    ->Args({1, 2})
    ->Args({1, 20})
    ->ArgNames({"adhesion", "w_x10"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
