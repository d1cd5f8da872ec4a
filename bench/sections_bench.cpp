// Wall time of a beam of sections and layers against the uniform beam: the cantilever switch
// (examples/switch/cantilever_switch.toml) at m = 100 as it is, and rewritten as 5 sections of a
// 3-layer stack (titanium, gold, a thin nitride cap; the stack's stresses curl it up): `modes`
// (modal_study, 5 modes, pinned supports), `pullin` (trace_pullin with the frequencies under bias)
// and the 50 us switching transient after a step to 1.2 V_PI, full FE model and reduced (8 modes),
// at the example's rtol 1e-8 and at 1e-6.

#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "modal/modal_analysis.hpp"
#include "statics/pullin.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

const char* const kLayers =
    "\n[[materials]]\nname = \"titanium\"\nyoungs_modulus = \"116 GPa\"\ndensity = \"4506 kg/m^3\"\n"
    "poisson_ratio = 0.32\nresidual_stress = \"200 MPa\"\n"
    "[[materials]]\nname = \"gold\"\nyoungs_modulus = \"79 GPa\"\ndensity = \"19300 kg/m^3\"\npoisson_ratio = 0.42\n"
    "residual_stress = \"20 MPa\"\nstress_gradient = 2e12\n"
    "[[materials]]\nname = \"nitride\"\nyoungs_modulus = \"250 GPa\"\ndensity = \"3100 kg/m^3\"\npoisson_ratio = 0.23\n"
    "residual_stress = \"100 MPa\"\n";

std::string section(double from, double to, const char* width, const char* gold) {
    return "[[beam.sections]]\nfrom = " + std::to_string(from) + "\nto = " + std::to_string(to) + "\nwidth = \"" + width +
           "\"\nlayers = [{ material = \"titanium\", thickness = \"50 nm\" }, { material = \"gold\", thickness = \"" +
           gold + "\" }, { material = \"nitride\", thickness = \"100 nm\" }]\n";
}

// The switch example at m = 100, uniform (layered = false) or of 5 layered sections.
vi::Case switch_case(bool layered) {
    const std::string path = std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch.toml";
    vi::Case c = vi::read_case_file(path);
    if (layered) {
        std::string text = std::string(kLayers) + section(0.0, 0.2, "20 um", "1.8 um") + section(0.2, 0.4, "30 um", "1.8 um") +
                           section(0.4, 0.7, "40 um", "2 um") + section(0.7, 0.9, "30 um", "2 um") +
                           section(0.9, 1.0, "20 um", "2 um");
        // Appended after the example's last table: the sections and materials are arrays of tables.
        std::ifstream in(path);
        std::stringstream body;
        body << in.rdbuf();
        c = vi::read_case_text(body.str() + text, "layered_switch.toml");
    }
    c.beam.elements = 100;
    return c;
}

void BM_Modes(benchmark::State& state) {
    const vi::Case c = switch_case(state.range(0) != 0);
    vi::ModalStudy s;
    for (auto _ : state) {
        s = vi::modal_study(c, 5, vi::SupportModel::pin);
        benchmark::DoNotOptimize(&s);
    }
}
BENCHMARK(BM_Modes)->Arg(0)->Arg(1)->ArgName("layered")->Unit(benchmark::kMillisecond);

void BM_Pullin(benchmark::State& state) {
    const vi::Case c = switch_case(state.range(0) != 0);
    vi::PullinResult r;
    for (auto _ : state) {
        r = vi::trace_pullin(c);
        benchmark::DoNotOptimize(r.branch.data());
    }
    state.counters["V_PI"] = r.pullin ? r.pullin->voltage : 0.0;
}
BENCHMARK(BM_Pullin)->Arg(0)->Arg(1)->ArgName("layered")->Unit(benchmark::kMillisecond);

// The 50 us transient after a step to 1.2 V_PI (its own), CVODE at rtol 10^-range(2) (8: the
// example's own, as `simulate` runs it), range(1) reduced modes (0: the full model); counters: the
// first contact time and the episodes.
void BM_SwitchTransient(benchmark::State& state) {
    vi::Case c = switch_case(state.range(0) != 0);
    const vi::PullinResult p = vi::trace_pullin(c);
    c.electrodes.at(0).voltage = 1.2 * p.pullin.value().voltage;
    c.solver.horizon = 50e-6;
    c.solver.rtol = std::pow(10.0, -static_cast<double>(state.range(2)));
    c.solver.reduced_modes = static_cast<int>(state.range(1));
    vi::SimulationOptions o;
    o.history = false;
    o.energy = false;
    vi::SimulationRun r;
    for (auto _ : state) {
        r = vi::run_simulation(c, o);
        benchmark::DoNotOptimize(&r);
    }
    state.counters["t_on_us"] = r.result.episodes.empty() ? 0.0 : r.result.episodes[0].t_on * 1e6;
    state.counters["episodes"] = static_cast<double>(r.result.episodes.size());
}
BENCHMARK(BM_SwitchTransient)
    ->Args({0, 0, 8})
    ->Args({1, 0, 8})
    ->Args({0, 8, 8})
    ->Args({1, 8, 8})
    ->Args({0, 0, 6})
    ->Args({1, 0, 6})
    ->Args({0, 8, 6})
    ->Args({1, 8, 6})
    ->ArgNames({"layered", "reduced_modes", "rtol_exp"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
