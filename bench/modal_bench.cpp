// Modal solve time of the paper's cantilever for growing meshes (m = 50, 200, 1000).

#include <benchmark/benchmark.h>

#include "modal/modal_analysis.hpp"
#include "model/case.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

vi::Case paper_cantilever(int elements) {
    vi::Case c;
    c.name = "bench";
    c.beam = {117e-6, 30e-6, 2e-6, elements, vi::EndCondition::clamped, vi::EndCondition::free};
    c.material = {207e9, 8902.0, 0.31, false};
    vi::Support s;
    s.position = 1.0;
    s.stiffness = 50.0;
    c.supports.push_back(s);
    return c;
}

// Five bending and five axial modes of the unsupported and the pinned beam, shape features included.
void BM_ModalStudy(benchmark::State& state) {
    const vi::Case c = paper_cantilever(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        vi::ModalStudy study = vi::modal_study(c, 5, vi::SupportModel::pin);
        benchmark::DoNotOptimize(study.ratios.data());
    }
    state.counters["elements"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_ModalStudy)->Arg(50)->Arg(200)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
