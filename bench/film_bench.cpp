// Wall time of the cantilever switch's 50 us switching transient at m = 50 (CVODE, full FE model)
// in vacuum (examples/switch/cantilever_switch.toml) against the same switch in air with the squeeze
// film (cantilever_switch_air.toml) at 1 atm and lower pressures: the cost of the film, a distributed
// nonlinear element on 80 % of the beam's DOFs (the aim: under 1 s).

#include <benchmark/benchmark.h>

#include <string>

#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

// range(0): 0 = vacuum; otherwise the pressure in Pa.
vi::Case switch_case(long pressure) {
    const std::string file = pressure == 0 ? "cantilever_switch.toml" : "cantilever_switch_air.toml";
    vi::Case c = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/" + file);
    if (pressure != 0) c.air->pressure = static_cast<double>(pressure);
    c.beam.elements = 50;
    c.solver.horizon = 50e-6;
    return c;
}

void BM_SwitchTransientWithFilm(benchmark::State& state) {
    const vi::Case c = switch_case(state.range(0));
    vi::SimulationOptions o;
    o.history = false;
    o.energy = false;
    vi::SimulationRun r;
    for (auto _ : state) {
        r = vi::run_simulation(c, o);
        benchmark::DoNotOptimize(r.result.episodes.data());
    }
    state.counters["closing_us"] = r.switching && r.switching->closing_time ? *r.switching->closing_time * 1e6 : -1.0;
    state.counters["bounces"] = r.switching ? r.switching->bounces : -1;
    state.counters["episodes"] = static_cast<double>(r.result.episodes.size());
    state.counters["steps"] = r.result.stats.steps;
    state.counters["setups"] = r.result.stats.decompositions;
    state.counters["events"] = r.result.stats.events;
}
BENCHMARK(BM_SwitchTransientWithFilm)
    ->Arg(0)
    ->Arg(101325)
    ->Arg(1000)
    ->Arg(100)
    ->Arg(10)
    ->ArgNames({"pressure_Pa"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
