// Wall time of a 1000-point support-position sweep at m = 50 (the paper's free-impact example,
// examples/paper/free_impact_tip.toml, x0/l from 0.3 to 1) on 1 and 2 worker threads: total
// seconds and points per second. VI_SWEEP_BENCH_POINTS=N runs N points instead (quick checks).

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "sweep/grid.hpp"
#include "sweep/runner.hpp"
#include "io/case_reader.hpp"
#include "sweep/table.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

// CPU time of the whole process (every thread) [s]: with wall time, how many cores the sweep got
// (the machine may be shared).
double process_cpu_s() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::size_t point_count() {
    const char* env = std::getenv("VI_SWEEP_BENCH_POINTS");
    const long n = env ? std::atol(env) : 0;
    return n > 0 ? static_cast<std::size_t>(n) : 1000;
}

// One timed pass over every point of a grid: points failed, wall seconds, process CPU seconds.
struct SweepTiming {
    std::size_t failed = 0;
    double seconds = 0.0;
    double cpu = 0.0;
};

SweepTiming time_sweep(benchmark::State& state, const vi::Case& base, const vi::SweepGrid& grid,
                       const vi::SweepSettings& settings, std::size_t column_count, int threads) {
    std::vector<std::size_t> all(grid.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    SweepTiming t;
    for (auto _ : state) {
        t.failed = 0;
        const double cpu0 = process_cpu_s();
        const auto t0 = std::chrono::steady_clock::now();
        vi::run_sweep_points(base, grid, all, settings, threads, [&](const vi::SweepPointResult& r) {
            // The row text is part of what a sweep does for every point.
            benchmark::DoNotOptimize(vi::sweep_csv_row(r, column_count));
            if (!r.ok()) ++t.failed;
        });
        t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        t.cpu = process_cpu_s() - cpu0;
    }
    return t;
}

void BM_SupportPositionSweep(benchmark::State& state) {
    const vi::Case base = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    const std::size_t n = point_count();
    const vi::SweepGrid grid =
        vi::parse_sweep_grid({"supports[0].position=0.3:1:" + std::to_string(n), "beam.elements=50"}, base);
    const vi::SweepSettings settings;
    const auto columns = vi::sweep_result_columns(settings.analysis, settings.modes);
    const int threads = static_cast<int>(state.range(0));
    const auto [failed, seconds, cpu] = time_sweep(state, base, grid, settings, columns.size(), threads);
    const double rate = static_cast<double>(grid.size()) / seconds;
    state.counters["points"] = static_cast<double>(grid.size());
    state.counters["failed_points"] = static_cast<double>(failed);
    state.counters["total_s"] = seconds;
    state.counters["points_per_s"] = rate;
    state.counters["cpu_s"] = cpu;
    state.counters["cores_used"] = cpu / seconds;
    std::printf(
        "sweep: %zu support positions at m = 50 on %d thread%s: %.2f s, %.2f points/s, %.1f ms of CPU per point, "
        "%.2f cores busy on average (%zu points failed)\n",
        grid.size(), threads, threads == 1 ? "" : "s", seconds, rate, 1e3 * cpu / static_cast<double>(grid.size()),
        cpu / seconds, failed);
}
BENCHMARK(BM_SupportPositionSweep)->Arg(1)->Arg(2)->ArgName("threads")->Iterations(1)->UseRealTime()->Unit(
    benchmark::kSecond);

// The position x stiffness grid of docs/model.md §11: 60 support positions over 0.3..1 (slowest)
// times 50 contact stiffnesses over 100..10000 N/m (log), 3000 points of the free-impact example
// (m = 50, 150 us), as `vibroimpact sweep --set 'supports[0].position=0.3:1:60' --set
// 'supports[0].stiffness=log:100:10000:50'` runs them, on range(0) threads.
// VI_GRID_BENCH_POSITIONS=N takes N positions instead of 60 (quick checks).
void BM_PositionStiffnessGrid(benchmark::State& state) {
    const vi::Case base = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    const char* env = std::getenv("VI_GRID_BENCH_POSITIONS");
    const long positions = env && std::atol(env) > 0 ? std::atol(env) : 60;
    const vi::SweepGrid grid = vi::parse_sweep_grid(
        {"supports[0].position=0.3:1:" + std::to_string(positions), "supports[0].stiffness=log:100:10000:50"}, base);
    vi::SweepSettings settings;
    settings.supports = static_cast<int>(base.supports.size());
    const auto columns = vi::sweep_result_columns(settings.analysis, settings.modes, settings.supports);
    const int threads = static_cast<int>(state.range(0));
    const auto [failed, seconds, cpu] = time_sweep(state, base, grid, settings, columns.size(), threads);
    const double rate = static_cast<double>(grid.size()) / seconds;
    state.counters["points"] = static_cast<double>(grid.size());
    state.counters["failed_points"] = static_cast<double>(failed);
    state.counters["points_per_s"] = rate;
    state.counters["cpu_ms_per_point"] = 1e3 * cpu / static_cast<double>(grid.size());
    state.counters["cores_used"] = cpu / seconds;
    std::printf("grid: %ld positions x 50 stiffnesses (%zu points) at m = 50 on %d thread%s: %.2f s, %.1f points/s, "
                "%.2f ms of CPU per point, %.2f cores busy (%zu points failed)\n",
                positions, grid.size(), threads, threads == 1 ? "" : "s", seconds, rate,
                1e3 * cpu / static_cast<double>(grid.size()), cpu / seconds, failed);
}
BENCHMARK(BM_PositionStiffnessGrid)->Arg(2)->ArgName("threads")->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
