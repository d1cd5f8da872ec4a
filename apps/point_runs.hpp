#pragma once
// The points of a sweep or of a sample design computed on every MPI rank and worker thread, with
// the journal, progress line, resume and point timeout: what `sweep` and `uq` share.

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "model/case.hpp"
#include "progress.hpp"
#include "sweep/columns.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"
#include "sweep/store.hpp"
#include "sweep/table.hpp"

namespace vi::cli {

// What every rank knows before the first point: the case, the points and the columns.
struct PointRunPlan {
    Case base;
    SweepGrid grid;
    SweepSettings settings;
    std::vector<SweepColumn> columns;
    std::string fingerprint;  // of everything that decides the rows (the journal's identity)
    std::string csv_header;
};

struct PointRunOptions {
    std::string out_dir;  // journal's folder; empty: rows in memory only
    bool resume = false;
    bool retry_failed = false;
    int threads = 0;      // per process; 0: the CPUs this process may use, shared among ranks
    ProgressSettings progress;    // --progress, --progress-interval
    std::string what = "sweep";   // the command, as the progress report names it
    std::string unit = "points";  // what it counts
};

// The run options of a command's options o (any struct with out_dir, resume, retry_failed, threads and
// progress, as sweep's and uq's have).
template <class CommandOptions>
PointRunOptions point_run_options(const CommandOptions& o, std::string what, std::string unit) {
    return {o.out_dir, o.resume, o.retry_failed, o.threads, o.progress, std::move(what), std::move(unit)};
}

// The root's last step with the store of every row (complete, or not when the run was stopped) and
// the run's figures; returns the exit code.
using FinishOnRoot = std::function<int(const PointRunPlan& plan, SweepStore& store, const SweepRunInfo& info)>;

// Starts the ranks (MPI under a launcher), makes the plan on every rank (make_plan may throw
// InputError: exit 2 on every rank, printed once; so may a bad --progress), opens the store on the
// root, computes every point not done yet with the root's progress report, then calls finish on
// the root. Every rank returns the
// root's exit code.
int run_points_on_ranks(const PointRunOptions& o, const std::function<PointRunPlan()>& make_plan,
                        const FinishOnRoot& finish);

// Exit code of a run stopped before every point was done: 128 + the signal (130 for SIGINT, 143
// for SIGTERM; 130 when the stop came from another MPI rank).
int interrupted_exit_code();

// What a stopped run prints on stderr (how many points are done, where they are kept and how to
// resume) and returns: interrupted_exit_code().
int report_interrupted(const char* command, const std::string& out_dir, const SweepStore& store);

}  // namespace vi::cli
