// `vibroimpact sweep CASE --set PATH=SPEC ...`: one analysis per point of a parameter grid, on every
// core and, under mpirun, on every rank; a journal lets an interrupted sweep resume.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sweep/case_paths.hpp"
#include "model/parallel_for.hpp"
#include "sweep/identity.hpp"
#include "sweep/ranks.hpp"
#include "sweep/runner.hpp"
#include "commands.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "io/text_file.hpp"
#include "model/run_control.hpp"
#include "sweep/store.hpp"
#include "sweep/table.hpp"
#include "support_model_option.hpp"
#include "stop_signals.hpp"
#include "progress.hpp"

#ifdef VI_HAVE_MPI
#include "sweep/mpi.hpp"
#endif

namespace vi::cli {
namespace {

// Exit code of a sweep stopped before every point was done: 128 + the signal (130 for SIGINT, 143
// for SIGTERM; 130 when the stop came from another MPI rank). main.cpp installs the handlers: the
// first signal sets the stop flag (model/run_control.hpp), which stops new points from starting and
// makes the solvers of running points abandon them within milliseconds; finished points are already
// in the journal. A second signal ends the process at once.
int interrupted_exit_code() { return kExitStoppedBase + (stop_signal() > 0 ? stop_signal() : SIGINT); }

struct SweepCommandOptions {
    std::string case_path;
    std::vector<std::string> sets;
    std::string analysis = "simulate";
    std::string out_dir;
    int threads = 0;
    int modes = 3;
    std::string support_model = "pin";
    bool resume = false;
    bool retry_failed = false;
    double point_timeout = 60.0;
    ProgressSettings progress;
};

// What every rank knows before the first point: the case, the grid and the columns.
struct Plan {
    Case base;
    SweepGrid grid;
    SweepSettings settings;
    std::vector<SweepColumn> columns;
    std::string fingerprint;
    std::string csv_header;
    ProgressStyle progress = ProgressStyle::none;
};

Plan make_plan(const SweepCommandOptions& o) {
    if (o.resume && o.out_dir.empty()) throw InputError("--resume: needs --out DIR, the folder holding the journal");
    if (o.retry_failed && !o.resume) throw InputError("--retry-failed: goes with --resume (failed points of a journal)");
    Plan p;
    p.progress = progress_style(o.progress);
    std::string reason;
    const auto text = file_text(o.case_path, reason);
    if (!text) throw InputError(one_line(o.case_path + ": cannot read file (" + reason + ")"));
    p.base = read_case_text(*text, o.case_path);
    p.grid = parse_sweep_grid(o.sets, p.base);
    p.settings.analysis = o.analysis == "modes" ? SweepAnalysis::modes : SweepAnalysis::simulate;
    p.settings.modes = o.modes;
    p.settings.support_model = parse_support_model(o.support_model);
    p.settings.point_timeout = o.point_timeout;
    p.columns = sweep_result_columns(p.settings.analysis, p.settings.modes);
    p.fingerprint = fingerprint_of(sweep_identity_text(*text, p.grid, p.settings));
    p.csv_header = sweep_csv_header(p.grid, p.columns);
    return p;
}

// Runs one step of the command, turning what it throws into an exit code and a message.
template <class Step>
int attempt(Step&& step, std::string& message) {
    try {
        step();
        return kExitOk;
    } catch (const InputError& e) {
        message = e.what();
        return kExitBadInput;
    } catch (const std::exception& e) {
        message = e.what();
        return kExitFailure;
    }
}

void print_problem(int code, const std::string& message, int rank) {
    const std::string who = rank == 0 ? "" : "(rank " + std::to_string(rank) + ") ";
    std::fprintf(stderr, "vibroimpact: %s: %s%s\n", code == kExitBadInput ? "error" : "failure", who.c_str(),
                 message.c_str());
}

// Makes a step's outcome collective: every rank returns the worst exit code. A rank with a problem
// prints it, unless the root has one too (a problem every rank meets is printed once).
int agree(SweepRanks& ranks, int code, const std::string& message) {
    const int root_code = ranks.broadcast(code);
    const int worst = ranks.max_over_ranks(code);
    if (code != kExitOk && (ranks.rank() == 0 || root_code == kExitOk)) print_problem(code, message, ranks.rank());
    return worst;
}

std::unique_ptr<SweepRanks> start_ranks() {
    if (!launched_by_mpi()) return std::make_unique<SingleProcess>();
#ifdef VI_HAVE_MPI
    return start_mpi_ranks();
#else
    throw InputError("this vibroimpact was built without MPI: run the sweep without mpirun (install libopenmpi-dev "
                     "and rebuild to spread it over processes)");
#endif
}

// --threads, or by default the CPUs this process may use (affinity, cgroup quota) shared among the
// ranks that may run on the same CPUs (all ranks of the machine unless the launcher binds them).
int worker_threads(const SweepCommandOptions& o, const SweepRanks& ranks) {
    if (o.threads > 0) return o.threads;
    return std::max(1, resolve_thread_count(0) / std::max(1, ranks.ranks_sharing_cpus()));
}

// The root's last step: the files of a complete sweep, or how to resume an interrupted one.
int finish_on_root(const SweepCommandOptions& o, const Plan& plan, SweepStore& store, SweepRunInfo info) {
    if (!store.complete()) {
        if (o.out_dir.empty()) {
            std::fprintf(stderr,
                         "vibroimpact: sweep interrupted after %zu of %zu points; nothing kept (with --out DIR a "
                         "sweep can be resumed)\n",
                         store.done(), store.points());
        } else {
            std::fprintf(stderr,
                         "vibroimpact: sweep interrupted: %zu of %zu points done, kept in %s; run the same command "
                         "with --resume to finish it\n",
                         store.done(), store.points(), store.journal_path().c_str());
        }
        return interrupted_exit_code();
    }
    const auto failures = store.failures();
    info.points_done = store.done();
    info.failed = failures.size();
    info.failures = failures;
    info.computed_this_run = store.computed();
    info.from_journal = store.from_journal();
    if (o.out_dir.empty()) {
        std::fputs(store.csv().c_str(), stdout);
    } else {
        const std::string json = sweep_summary_json(plan.grid, info).dump(2) + "\n";
        const CommitSection commit;
        store.finish(o.out_dir, json);
        std::printf("Written %zu points to %s/%s and %s\n", store.points(), o.out_dir.c_str(), SweepStore::kCsvName,
                    SweepStore::kJsonName);
    }
    if (!failures.empty()) {
        std::fprintf(stderr, "vibroimpact: sweep: %zu of %zu points failed (the status column says why)\n",
                     failures.size(), store.points());
    }
    return kExitOk;
}

int run_sweep(const SweepCommandOptions& o) {
    std::unique_ptr<SweepRanks> ranks;
    try {
        ranks = start_ranks();
    } catch (const InputError& e) {
        if (launcher_rank() == 0) print_problem(kExitBadInput, e.what(), 0);
        return kExitBadInput;
    }
    const bool root = ranks->rank() == 0;
    std::string message;

    Plan plan;
    int code = attempt([&] { plan = make_plan(o); }, message);
    if ((code = agree(*ranks, code, message)) != kExitOk) return code;

    std::optional<SweepStore> store;
    if (root) {
        code = attempt([&] {
            store.emplace(o.out_dir, o.resume, plan.grid.size(), plan.fingerprint, plan.csv_header, o.retry_failed);
        }, message);
    }
    if ((code = agree(*ranks, code, message)) != kExitOk) return code;

    const std::vector<std::size_t> todo = ranks->broadcast(root ? store->todo() : std::vector<std::size_t>{});
    const std::vector<std::size_t> mine = share_of_rank(todo, ranks->rank(), ranks->size());
    const int threads = worker_threads(o, *ranks);
    const std::size_t result_columns = plan.columns.size();

    // Only the root reports: the other ranks' points reach it as they finish.
    Progress progress("sweep", "points", plan.grid.size(), root ? store->done() : 0,
                      root ? plan.progress : ProgressStyle::none, o.progress.interval_s);
    RunningPoints running;
    const LocalRun local = [&](const PointSink& emit, const std::atomic<bool>& stop) {
        run_sweep_points(
            plan.base, plan.grid, mine, plan.settings, threads,
            [&](const SweepPointResult& r) { emit({r.index, r.status, sweep_csv_row(r, result_columns)}); }, &stop,
            &running);
    };
    const PointSink sink = [&](const FinishedPoint& p) {
        store->add(p);
        progress.advance();
    };

    const auto t0 = std::chrono::steady_clock::now();
    {
        // The line keeps moving while a point is slow: redrawn twice a second with the slowest point.
        const ProgressTicker ticker(progress, [&] {
            const auto [index, seconds] = running.slowest();
            // A point is named once it has run 2 s: the usual points pass too fast to be worth it.
            progress.set_note(index != SIZE_MAX && seconds >= 2.0
                                  ? "slowest: point " + std::to_string(index) + ", " + duration_text(seconds) + " running"
                                  : "");
        });
        code = attempt([&] { ranks->collect(local, sink, stop_flag()); }, message);
    }
    progress.finish();
    if (code != kExitOk) {
        if (root) print_problem(code, message, 0);
        return ranks->broadcast(code);
    }

    if (root) {
        SweepRunInfo info;
        info.case_path = o.case_path;
        info.case_name = plan.base.name;
        info.settings = plan.settings;
        info.columns = plan.columns;
        info.fingerprint = plan.fingerprint;
        info.threads = threads;
        info.processes = ranks->size();
        info.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        int finished = kExitOk;
        code = attempt([&] { finished = finish_on_root(o, plan, *store, info); }, message);
        if (code != kExitOk) {
            print_problem(code, message, 0);
        } else {
            code = finished;
        }
    }
    return ranks->broadcast(code);
}

std::string paths_help() {
    std::string s = "PATH is one of (i: support or load number from 0, k: 0 or 1):\n ";
    std::size_t width = 1;
    for (const std::string& p : case_path_forms()) {
        if (width + p.size() + 1 > 100) {
            s += "\n ";
            width = 1;
        }
        s += " " + p;
        width += p.size() + 1;
    }
    return s + "\nSee docs/sweeps.md for the columns, resuming, MPI and exit codes.";
}

}  // namespace

CommandBody add_sweep_command(CLI::App& app) {
    auto opt = std::make_shared<SweepCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "sweep", "Run an analysis over a grid of case values, on every core (and every MPI rank under mpirun)");
    sub->add_option("case", opt->case_path, "Case file (TOML)")->required();
    sub->add_option("--set", opt->sets,
                    "PATH=SPEC: a value of the case and the values it takes, in SI units (m, Pa, N/m, N s/m, s; "
                    "positions as x/l; gap and prestress in m). SPEC: a list 0.5,0.67,0.78, a range "
                    "start:stop:count or log:start:stop:count. Several --set make a full grid (the last varies "
                    "fastest)")
        ->required()
        ->allow_extra_args(false)
        ->type_name("PATH=SPEC");
    sub->add_option("--analysis", opt->analysis, "What each point computes: simulate (transient) or modes")
        ->check(CLI::IsMember({"simulate", "modes"}))
        ->capture_default_str();
    CLI::Option* modes = sub->add_option("--modes", opt->modes, "Bending modes per point of a modes sweep")
                             ->check(CLI::Range(1, 100))
                             ->capture_default_str();
    CLI::Option* support_model = add_support_model_option(*sub, opt->support_model);
    sub->add_option("--out,-o", opt->out_dir,
                    "Folder for sweep.csv and sweep.json, and for the journal of finished points (otherwise the CSV "
                    "goes to stdout and an interrupted sweep is lost)");
    sub->add_flag("--resume", opt->resume, "Finish the sweep interrupted in --out DIR without redoing its points");
    sub->add_flag("--retry-failed", opt->retry_failed,
                  "With --resume: compute again the points the journal holds as failed (error or timeout)");
    sub->add_option("--point-timeout", opt->point_timeout,
                    "Wall-clock limit of one point [s]; a point that reaches it gets 'timeout: ...' in its status "
                    "and the sweep goes on (0: no limit)")
        ->check(CLI::Range(0.0, 1e9))
        ->capture_default_str();
    sub->add_option("--threads,-j", opt->threads,
                    "Worker threads per process (0: every CPU this process may use, its affinity and cgroup CPU "
                    "quota; under MPI, shared among the ranks that may use the same CPUs)")
        ->check(CLI::Range(0, 4096))
        ->capture_default_str();
    add_progress_options(*sub, opt->progress);
    sub->footer(paths_help());
    return [opt, modes, support_model]() {
        // Options a simulate sweep has no use for are refused rather than ignored.
        if (opt->analysis == "simulate") {
            for (const CLI::Option* o : {modes, support_model}) {
                if (o->count() > 0) throw InputError(o->get_name() + ": applies to --analysis modes, not to a simulate sweep");
            }
        }
        return run_sweep(*opt);
    };
}

}  // namespace vi::cli
