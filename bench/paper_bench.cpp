// Wall time of the whole `vibroimpact paper` run (study, figures with gnuplot, report, files) and of
// its parts. A figure, never a pass or fail:
//   vi_bench_paper [--threads N] [--repeat R] [--positions N] [--no-figures]
// --no-figures leaves out gnuplot (and the files), to time the study alone.

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "study/paper/claims.hpp"
#include "study/paper/study.hpp"
#include "model/parallel_for.hpp"
#include "io/output_files.hpp"
#include "plot/figure_gnuplot.hpp"
#include "study/paper/figures.hpp"
#include "study/paper/report.hpp"
#include "peak_rss.hpp"  // prints the peak RSS at exit

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// CPU seconds (user + system) of this process and of its finished children (gnuplot) so far. On a
// machine shared with other work the wall time says little; the CPU time divided by the cores is
// what the run would take on its own.
double cpu_seconds() {
    double s = 0.0;
    for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
        rusage u{};
        getrusage(who, &u);
        s += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 0, repeat = 3, positions = 50;
    bool figures = true;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
        else if (a == "--positions" && i + 1 < argc) positions = std::atoi(argv[++i]);
        else if (a == "--no-figures") figures = false;
        else {
            std::fprintf(stderr, "usage: vi_bench_paper [--threads N] [--repeat R] [--positions N] [--no-figures]\n");
            return 2;
        }
    }
    const auto gnuplot = vi::find_gnuplot();
    if (figures && !gnuplot) {
        std::fprintf(stderr, "vi_bench_paper: gnuplot not found (use --no-figures to time the study alone)\n");
        return 1;
    }
    vi::PaperStudyOptions o;
    o.cases = vi::load_paper_cases("");
    o.positions = positions;
    o.threads = threads;
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "vi_bench_paper";
    std::printf("vibroimpact paper: %d support positions x %zu meshes, %d modal positions, %d prestress values; %d thread(s); %s\n",
                positions, o.meshes.size(), o.modal_positions, o.prestress_points, vi::resolve_thread_count(threads),
                figures ? "gnuplot and files included" : "study only (no gnuplot, no files)");
    std::printf("%-4s %8s %8s %8s %8s %8s | CPU s: %7s %7s %7s %7s %7s | %s\n", "run", "total_s", "cpu_s", "study_s", "figs_s", "files_s",
                "scans", "prestr", "fig3", "fig11", "modes", "scan transients per CPU s");
    std::vector<double> totals, cpus;
    for (int r = 1; r <= repeat; ++r) {
        const auto t0 = Clock::now();
        const double c0 = cpu_seconds();
        const vi::PaperStudy st = vi::run_paper_study(o);
        const double study_s = since(t0);
        double figs_s = 0.0, files_s = 0.0;
        if (figures) {
            const auto t1 = Clock::now();
            const auto claims = vi::paper_claims(st);
            const auto specs = vi::paper_figures(st);
            const auto rendered = vi::render_figures(*gnuplot, specs, threads);
            figs_s = since(t1);
            const auto t2 = Clock::now();
            vi::ReportRun run{"vibroimpact (bench)", "vi_bench_paper", figs_s, since(t0)};
            vi::write_output_files(out.string(), vi::paper_output_files(st, claims, specs, rendered, run));
            files_s = since(t2);
        }
        const double total = since(t0);
        const double cpu = cpu_seconds() - c0;
        totals.push_back(total);
        cpus.push_back(cpu);
        int scan_points = 0;
        for (const auto& s : st.position_scans) scan_points += static_cast<int>(s.points.size());
        const vi::StudyTiming& t = st.timing;
        std::printf("%-4d %8.2f %8.2f %8.2f %8.2f %8.2f | %14.2f %7.2f %7.2f %7.2f %7.2f | %.1f\n", r, total, cpu, study_s, figs_s, files_s,
                    t.position_scans_s, t.prestress_s, t.typical_s, t.forces_s, t.modes_s,
                    scan_points / std::max(1e-9, t.position_scans_s));
    }
    std::sort(totals.begin(), totals.end());
    std::sort(cpus.begin(), cpus.end());
    const int cores = vi::resolve_thread_count(threads);
    std::printf("wall: best %.2f s, median %.2f s over %d run(s); CPU: median %.2f s, i.e. %.2f s on %d core(s) of its own\n",
                totals.front(), totals[totals.size() / 2], repeat, cpus[cpus.size() / 2], cpus[cpus.size() / 2] / cores, cores);
    std::error_code ec;
    std::filesystem::remove_all(out, ec);
    return 0;
}
