#pragma once
// Sweep results as text: CSV header and rows (one row per point), and the JSON summary.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sweep/columns.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace vi {

// The header line (no newline): every swept path with its unit (case_path_column: "supports[0].gap_m"),
// the result columns, then "status".
std::string sweep_csv_header(const SweepGrid& grid, const std::vector<SweepColumn>& columns);

// One point's line (no newline), written by io/csv_writer.hpp: numbers as their shortest round-trip
// text, so that a row is the same whichever thread or process computed it; the missing-value marker
// for values the point does not define and for the results of a failed point (result_columns of
// them); text quoted as RFC 4180 needs.
std::string sweep_csv_row(const SweepPointResult& r, std::size_t result_columns);

// The status cell (last cell) of a line written by sweep_csv_row, unquoted: "ok" or "error: ...".
std::string sweep_row_status(std::string_view row);

// What the JSON summary reports besides the grid.
struct SweepRunInfo {
    std::string case_path;
    std::string case_name;
    SweepSettings settings;
    std::vector<SweepColumn> columns;
    std::string fingerprint;
    std::size_t points_done = 0;       // finished points, this run and before
    std::size_t failed = 0;            // of those, points whose status is an error
    std::vector<std::pair<std::size_t, std::string>> failures;  // (grid index, status), index order
    std::size_t computed_this_run = 0;
    std::size_t from_journal = 0;      // finished points taken over from an interrupted run
    int threads = 1;                   // worker threads per process
    int processes = 1;                 // MPI ranks
    double wall_s = 0.0;               // wall time of this run's points
};

// {"case", "case_name", "analysis", "axes": [{"path", "column", "setting", "unit", "values"}], "points",
// "done", "ok", "failed", "failures", "computed_this_run", "from_journal", "threads", "processes",
// "wall_s", "points_per_s", "columns": [{"name", "unit"}], "fingerprint"}.
nlohmann::json sweep_summary_json(const SweepGrid& grid, const SweepRunInfo& info);

}  // namespace vi
