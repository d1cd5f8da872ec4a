// Wall and CPU time of three spread studies on the example cantilever switch (m = 50) on 2 worker
// threads, as `vibroimpact uq` runs them: 1000 pull-in samples; 1000 switching transients of the
// reduced model (10 modes); Saltelli's runs for Sobol indices of 4 inputs with 512 base samples
// (3072 reduced-model transients; gaps are not varied there: a stop gap drawn wider than the
// electrode's lets the beam collapse onto it, which this model grinds through until the point
// timeout). Each prints the runs' time and the estimators' time apart.
// VI_UQ_BENCH_SCALE=F runs F times the samples (quick checks). A timing program: no pass or fail.

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "sweep/runner.hpp"
#include "sweep/table.hpp"
#include "uq/sample_design.hpp"
#include "uq/uq_summary.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

double process_cpu_s() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::size_t scaled(std::size_t n) {
    const char* env = std::getenv("VI_UQ_BENCH_SCALE");
    const double f = env ? std::atof(env) : 1.0;
    return std::max<std::size_t>(32, static_cast<std::size_t>(f * static_cast<double>(n)));
}

void study(const char* title, const vi::Case& base, vi::SweepAnalysis analysis, const std::vector<std::string>& vary,
           std::size_t n, bool sensitivity) {
    const int threads = 2;
    vi::SweepSettings settings;
    settings.analysis = analysis;
    settings.point_timeout = 60.0;  // as uq's default: a run that grinds is a failed run, counted
    const std::vector<vi::UqInput> inputs = vi::parse_uq_inputs(vary, base);
    const vi::SampleDesign design = vi::make_sample_design(inputs, n, vi::SamplingMethod::sobol, 1, sensitivity);
    const auto columns = vi::sweep_result_columns(analysis, settings.modes);
    std::vector<std::string> rows(design.runs());
    std::vector<std::size_t> all(design.runs());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    std::size_t failed = 0;
    const double cpu0 = process_cpu_s();
    const auto t0 = std::chrono::steady_clock::now();
    vi::run_sweep_points(base, design.grid, all, settings, threads, [&](const vi::SweepPointResult& r) {
        rows[r.index] = vi::sweep_csv_row(r, columns.size());
        failed += r.ok() ? 0 : 1;
    });
    const double run_s = seconds_since(t0), run_cpu = process_cpu_s() - cpu0;
    std::string csv = vi::sweep_csv_header(design.grid, columns) + "\n";
    for (const std::string& row : rows) csv += row + "\n";
    const auto t1 = std::chrono::steady_clock::now();
    vi::UqSettings s;
    s.analysis = vi::sweep_analysis_name(analysis);
    s.method = vi::SamplingMethod::sobol;
    const vi::UqTable table = vi::uq_table_from_csv(csv, inputs.size());
    const std::string json = vi::uq_summary_json(design, table, s).dump();
    const double summary_s = seconds_since(t1);
    std::printf("%s: %zu runs on %d threads: %.1f s wall, %.1f s CPU (%.1f ms CPU per run, %.2f cores busy), %zu "
                "failed; estimators %.2f s (%zu numeric columns, %zu bytes of uq.json)\n",
                title, design.runs(), threads, run_s, run_cpu, 1e3 * run_cpu / static_cast<double>(design.runs()),
                run_cpu / run_s, failed, summary_s, table.columns.size(), json.size());
    std::fflush(stdout);
}

}  // namespace

int main() {
    const std::string src = VI_SOURCE_DIR;
    const vi::Case sw = vi::read_case_file(src + "/examples/switch/cantilever_switch.toml");
    study("pull-in, 1000 samples, m = 50", sw, vi::SweepAnalysis::pullin,
          {"beam.thickness=normal:2um:0.05um", "electrodes[0].gap=normal:2um:0.05um"}, scaled(1000), false);
    vi::Case reduced = sw;
    reduced.solver.reduced_modes = 10;
    study("switching transient (reduced model, 10 modes), 1000 samples", reduced, vi::SweepAnalysis::simulate,
          {"supports[0].stiffness=lognormal:1000:0.2", "supports[0].damping_ratio=uniform:0.1:0.3"}, scaled(1000), false);
    study("Sobol indices, 4 inputs x 512 base samples (switching transients, reduced model)", reduced,
          vi::SweepAnalysis::simulate,
          {"beam.thickness=normal:2um:0.05um", "electrodes[0].voltage=normal:70:2",
           "supports[0].stiffness=lognormal:1000:0.2", "supports[0].damping_ratio=uniform:0.1:0.3"},
          scaled(512), true);
    return 0;
}
