// CVODE on refined meshes: the 50 us switching transient of examples/switch/cantilever_switch.toml
// (70 V step, contact stop under the free end) at m = 50, 100, 200, 400 elements, on the full FE
// model and on a reduced model, with the time of each run, its growth per doubling of m, the answers
// that must converge with m (closing time, bounces, stable contact) and the peak RSS so far (the
// rows run coarsest first, so it is each row's own peak or an earlier one's).
// A figure, never a pass or fail:
//   vi_bench_cvode_mesh [--reduced N] [--full-only | --reduced-only] [--min M] [--max M] [--rtol R] [--repeat K]
//                       [--state auto|modal|nodal]
// --state picks the full model's coordinates (CvodeOptions::state; the column `state` says which
// ran: modal or the FE DOFs).
// The runs go through the solver directly, without the case limits, so that a mesh above them can
// be timed too.

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "impacts/simulation.hpp"
#include "impacts/switching_ledger.hpp"
#include "io/case_reader.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double peak_rss_mib() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

struct Row {
    int elements = 0;
    double wall = 0.0, cpu = 0.0, rss = 0.0;
    double closing = 0.0, stable = 0.0;
    int bounces = 0, grouped = 0;
    long steps = 0;
    int basis = 0;
    bool nodal = false;
};

Row run(const vi::Case& base, int elements, int reduced, double rtol, int repeat, vi::CvodeOptions::State state) {
    vi::Case c = base;
    c.beam.elements = elements;
    c.solver.reduced_modes = reduced;
    c.solver.rtol = rtol;
    vi::SimulationOptions o;
    o.history = false;
    o.energy = false;
    Row row;
    row.elements = elements;
    row.wall = 1e300;
    row.cpu = 1e300;
    for (int k = 0; k < repeat; ++k) {
        const auto t0 = Clock::now();
        const double c0 = cpu_seconds();
        const vi::BuiltProblem built = vi::build_transient_problem(c);
        vi::CvodeOptions co = vi::cvode_options(c.solver);
        co.state = state;
        const vi::TransientResult r = vi::CvodeSolver(co).solve(built.problem, vi::transient_options(c.solver, o));
        row.wall = std::min(row.wall, std::chrono::duration<double>(Clock::now() - t0).count());
        row.cpu = std::min(row.cpu, cpu_seconds() - c0);
        std::vector<vi::LedgerContact> contacts;
        for (const auto& named : built.model.contacts) contacts.push_back({named.name, std::nullopt, std::nullopt});
        const vi::SwitchingLedger s = vi::switching_ledger(r, c.electrodes, built.model.omega1, contacts);
        row.closing = s.closing_time.value_or(NAN);
        row.stable = s.stable_contact.value_or(NAN);
        row.bounces = s.bounces;
        row.grouped = s.grouped_bounces;
        row.steps = static_cast<long>(r.stats.steps);
        row.basis = static_cast<int>(r.stats.basis_vectors);
        row.nodal = r.stats.nodal_state;
    }
    row.rss = peak_rss_mib();
    return row;
}

void header(const char* label) {
    std::printf("%s\n%8s %9s %9s %8s %9s %14s %14s %8s %8s %8s %6s %6s\n", label, "elements", "wall_s", "cpu_s",
                "growth", "rss_MiB", "closing_us", "stable_us", "bounces", "grouped", "steps", "basis", "state");
}

// The last row of `rows`, with its growth over the one before.
void print_last(const std::vector<Row>& rows) {
    const Row& r = rows.back();
    const double growth = rows.size() > 1 ? r.cpu / rows[rows.size() - 2].cpu : NAN;
    std::printf("%8d %9.3f %9.3f %8.2f %9.1f %14.9f %14.9f %8d %8d %8ld %6d %6s\n", r.elements, r.wall, r.cpu, growth,
                r.rss, r.closing * 1e6, r.stable * 1e6, r.bounces, r.grouped, r.steps, r.basis, r.nodal ? "fe" : "modal");
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    int reduced = 10, least = 50, most = 400, repeat = 1;
    bool reduced_runs = true, full_runs = true;
    double rtol = 0.0;
    vi::CvodeOptions::State state = vi::CvodeOptions::State::automatic;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--reduced" && i + 1 < argc) reduced = std::atoi(argv[++i]);
        else if (a == "--full-only") reduced_runs = false;
        else if (a == "--reduced-only") full_runs = false;
        else if (a == "--max" && i + 1 < argc) most = std::atoi(argv[++i]);
        else if (a == "--min" && i + 1 < argc) least = std::max(1, std::atoi(argv[++i]));
        else if (a == "--rtol" && i + 1 < argc) rtol = std::atof(argv[++i]);
        else if (a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
        else if (a == "--state" && i + 1 < argc && std::string(argv[i + 1]) == "modal") {
            state = vi::CvodeOptions::State::modal;
            ++i;
        } else if (a == "--state" && i + 1 < argc && std::string(argv[i + 1]) == "nodal") {
            state = vi::CvodeOptions::State::nodal;
            ++i;
        } else if (a == "--state" && i + 1 < argc && std::string(argv[i + 1]) == "auto") {
            ++i;
        } else {
            std::fprintf(stderr, "usage: vi_bench_cvode_mesh [--reduced N] [--full-only | --reduced-only] [--min M] [--max M] [--rtol R] "
                                 "[--repeat K] [--state auto|modal|nodal]\n");
            return 2;
        }
    }
    const vi::Case c = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch.toml");
    const double tol = rtol > 0.0 ? rtol : c.solver.rtol;
    std::printf("cantilever_switch.toml, 50 us, rtol %.0e; growth = cpu time over the previous row's\n", tol);
    std::vector<Row> full, red;
    if (full_runs) {
        header("full model");
        for (int m = least; m <= most; m *= 2) {
            full.push_back(run(c, m, 0, tol, repeat, state));
            print_last(full);
        }
    }
    if (reduced_runs) {
        header(("reduced model, " + std::to_string(reduced) + " modes").c_str());
        for (int m = least; m <= most; m *= 2) {
            red.push_back(run(c, m, reduced, tol, repeat, state));
            print_last(red);
        }
    }
    std::printf("peak RSS %.1f MiB\n", peak_rss_mib());
    return 0;
}
