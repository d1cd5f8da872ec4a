// The points of a sweep grid run for Python: their sweep.csv rows, with the progress report.
#pragma once

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "sweep/columns.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace vi::python {

struct PointRows {
    std::vector<std::string> rows;           // sweep.csv's row of each point, in grid order
    std::set<std::string> integer_columns;   // result columns that held whole numbers
};

// Runs every point of grid on `workers` threads with the GIL released (Ctrl-C stops them) and the
// progress report of `label` ("sweep", "uq") counting `unit` ("points", "runs") as the `progress` and
// `progress_interval` arguments ask; on_point, if given, sees each result as it lands.
PointRows run_point_rows(const Case& base, const SweepGrid& grid, const SweepSettings& settings, int workers,
                         const std::vector<SweepColumn>& columns, const char* label, const char* unit,
                         const std::optional<std::string>& progress_mode, double progress_interval,
                         const std::function<void(const SweepPointResult&)>& on_point = {});

}  // namespace vi::python
