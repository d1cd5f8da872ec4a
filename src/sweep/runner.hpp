#pragma once
// Runs the points of a sweep on worker threads; a point that fails records why and the rest go on.

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <utility>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sweep/columns.hpp"
#include "sweep/grid.hpp"
#include "fem/system.hpp"
#include "model/case.hpp"

namespace vi {

// The cells of a point for an analysis computed above this layer (stiction, air-q: the studies'
// code), in sweep_result_columns order; study/analyses/sweep_analyses.hpp supplies it.
using PointAnalysis = std::function<std::vector<SweepCell>(const Case&)>;

// What every point computes.
struct SweepSettings {
    SweepAnalysis analysis = SweepAnalysis::simulate;
    int modes = 3;                                  // bending modes of a modes sweep
    SupportModel support_model = SupportModel::pin; // supports in the supported modes
    double point_timeout = 60.0;                    // wall-clock limit of one point [s]; 0 = none
    int supports = 0;                               // the swept case's supports: a simulate sweep's per-support columns
    PointAnalysis study_analysis;                   // stiction and air-q only (with_study_analyses)
};

// Throws InputError("--analysis NAME: reason") when the case cannot have the analysis: pullin
// without an electrode, stiction without an adhesive support or adhesive dielectric layer, air-q
// with neither an electrode nor a [[films]] entry (its squeeze film); std::logic_error when a
// stiction or air-q analysis has no study_analysis.
void check_sweep_analysis(const Case& c, const SweepSettings& settings);

// The points being computed now and since when, for a progress line that shows a slow point.
class RunningPoints {
public:
    void started(std::size_t index);
    void finished(std::size_t index);
    // The point running longest and for how long [s]; index = SIZE_MAX when none runs.
    [[nodiscard]] std::pair<std::size_t, double> slowest() const;

private:
    mutable std::mutex mutex_;
    std::map<std::size_t, std::chrono::steady_clock::time_point> since_;
};

// One finished point: its swept values, its results (all empty when it failed) and its status,
// "ok", "error: <one-line reason>" or "timeout: <one-line reason>" (settings.point_timeout).
struct SweepPointResult {
    std::size_t index = 0;
    std::vector<double> parameters;  // in axis order [SI]
    std::vector<SweepCell> cells;    // sweep_result_columns order
    std::string status;
    [[nodiscard]] bool ok() const { return status == "ok"; }
};

// Computes point `index`: sets its values in the base case, checks the case (check_case), runs the
// analysis (a transient without history or energy ledger, or a modal study) within
// settings.point_timeout (a pullin point traces without the frequencies under bias). Never throws for a problem of the point itself: InputError and
// std::exception become the status. A stop (StopRequested, model/run_control.hpp) passes through.
SweepPointResult run_sweep_point(const Case& base, const SweepGrid& grid, std::size_t index,
                                 const SweepSettings& settings);

// Runs run_sweep_point for every index in `indices` on `threads` threads (0: all cores), handing
// the points out in the order given, and calls done(result) as each finishes, one call at a time
// (under a lock), in completion order. When *stop becomes true no further point starts, and the
// solvers of those running abandon them (they check the stop flag, model/run_control.hpp): an
// abandoned point is not reported. Returns how many points were reported. An exception from `done`
// stops the loop and is rethrown once the workers have joined. `running`, if given, follows which
// points are being computed.
std::size_t run_sweep_points(const Case& base, const SweepGrid& grid, const std::vector<std::size_t>& indices,
                             const SweepSettings& settings, int threads,
                             const std::function<void(const SweepPointResult&)>& done,
                             const std::atomic<bool>* stop = nullptr, RunningPoints* running = nullptr);

}  // namespace vi
