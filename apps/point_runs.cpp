#include "point_runs.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "model/input_error.hpp"
#include "model/parallel_for.hpp"
#include "model/run_control.hpp"
#include "stop_signals.hpp"
#include "sweep/ranks.hpp"

#ifdef VI_HAVE_MPI
#include "sweep/mpi.hpp"
#endif

namespace vi::cli {
namespace {

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
int worker_threads(const PointRunOptions& o, const SweepRanks& ranks) {
    if (o.threads > 0) return o.threads;
    return std::max(1, resolve_thread_count(0) / std::max(1, ranks.ranks_sharing_cpus()));
}

}  // namespace

// The first signal sets the stop flag (model/run_control.hpp), which stops new points from starting
// and makes the solvers of running points abandon them within milliseconds; finished points are
// already in the journal. A second signal ends the process at once.
int interrupted_exit_code() { return kExitStoppedBase + (stop_signal() > 0 ? stop_signal() : SIGINT); }

int report_interrupted(const char* command, const std::string& out_dir, const SweepStore& store) {
    if (out_dir.empty()) {
        std::fprintf(stderr,
                     "vibroimpact: %s interrupted after %zu of %zu points; nothing kept (with --out DIR it can be "
                     "resumed)\n",
                     command, store.done(), store.points());
    } else {
        std::fprintf(stderr,
                     "vibroimpact: %s interrupted: %zu of %zu points done, kept in %s; run the same command with "
                     "--resume to finish it\n",
                     command, store.done(), store.points(), store.journal_path().c_str());
    }
    return interrupted_exit_code();
}

int run_points_on_ranks(const PointRunOptions& o, const std::function<PointRunPlan()>& make_plan,
                        const FinishOnRoot& finish) {
    std::unique_ptr<SweepRanks> ranks;
    try {
        ranks = start_ranks();
    } catch (const InputError& e) {
        if (launcher_rank() == 0) print_problem(kExitBadInput, e.what(), 0);
        return kExitBadInput;
    }
    const bool root = ranks->rank() == 0;
    std::string message;

    PointRunPlan plan;
    ProgressStyle style = ProgressStyle::none;
    int code = attempt([&] {
        style = progress_style(o.progress);
        plan = make_plan();
    }, message);
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
    Progress progress(o.what, o.unit, plan.grid.size(), root ? store->done() : 0, root ? style : ProgressStyle::none,
                      o.progress.interval_s);
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
        info.case_name = plan.base.name;
        info.settings = plan.settings;
        info.columns = plan.columns;
        info.fingerprint = plan.fingerprint;
        info.threads = threads;
        info.processes = ranks->size();
        info.wall_s = seconds_since(t0);
        info.points_done = store->done();
        info.computed_this_run = store->computed();
        info.from_journal = store->from_journal();
        int finished = kExitOk;
        code = attempt([&] { finished = finish(plan, *store, info); }, message);
        if (code != kExitOk) {
            print_problem(code, message, 0);
        } else {
            code = finished;
        }
    }
    return ranks->broadcast(code);
}

}  // namespace vi::cli
