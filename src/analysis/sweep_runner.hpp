#pragma once
// Runs the points of a sweep on worker threads; a point that fails records why and the rest go on.

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "analysis/sweep_columns.hpp"
#include "analysis/sweep_grid.hpp"
#include "fem/system.hpp"
#include "model/case.hpp"

namespace vi {

// What every point computes.
struct SweepSettings {
    SweepAnalysis analysis = SweepAnalysis::simulate;
    int modes = 3;                                  // bending modes of a modes sweep
    SupportModel support_model = SupportModel::pin; // supports in the supported modes
};

// One finished point: its swept values, its results (all empty when it failed) and its status,
// "ok" or "error: <one-line reason>".
struct SweepPointResult {
    std::size_t index = 0;
    std::vector<double> parameters;  // in axis order [SI]
    std::vector<SweepCell> cells;    // sweep_result_columns order
    std::string status;
    [[nodiscard]] bool ok() const { return status == "ok"; }
};

// Computes point `index`: sets its values in the base case, checks the case (check_case), runs the
// analysis (a transient without history or energy ledger, or a modal study). Never throws for a
// problem of the point itself: InputError and std::exception become the status.
SweepPointResult run_sweep_point(const Case& base, const SweepGrid& grid, std::size_t index,
                                 const SweepSettings& settings);

// Runs run_sweep_point for every index in `indices` on `threads` threads (0: all cores), handing
// the points out in the order given, and calls done(result) as each finishes, one call at a time
// (under a lock), in completion order. When *stop becomes true no further point starts; those
// running finish and are reported. Returns how many points ran. An exception from `done` stops
// the loop and is rethrown once the workers have joined.
std::size_t run_sweep_points(const Case& base, const SweepGrid& grid, const std::vector<std::size_t>& indices,
                             const SweepSettings& settings, int threads,
                             const std::function<void(const SweepPointResult&)>& done,
                             const std::atomic<bool>* stop = nullptr);

}  // namespace vi
