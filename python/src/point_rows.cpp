#include "point_rows.hpp"

#include <cstdint>
#include <variant>

#include "model/run_control.hpp"
#include "sweep/table.hpp"

namespace vi::python {

PointRows run_point_rows(const Case& base, const SweepGrid& grid, const SweepSettings& settings, int workers,
                         const std::vector<SweepColumn>& columns, const char* label, const char* unit,
                         const std::optional<std::string>& progress_mode, double progress_interval,
                         const std::function<void(const SweepPointResult&)>& on_point) {
    PointRows out;
    out.rows.resize(grid.size());
    std::vector<std::size_t> indices(grid.size());
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
    const PythonProgress report(progress_mode, progress_interval);
    Progress progress(label, unit, grid.size(), 0, report.style(), report.interval_s(), false, report.sink());
    run_released(
        [&] {
            const FinishProgress finish{progress};
            const ProgressTicker ticker(progress);
            run_sweep_points(
                base, grid, indices, settings, workers,
                [&](const SweepPointResult& r) {
                    out.rows[r.index] = sweep_csv_row(r, columns.size());
                    progress.advance();
                    for (std::size_t c = 0; c < r.cells.size() && c < columns.size(); ++c) {
                        if (std::holds_alternative<std::int64_t>(r.cells[c])) out.integer_columns.insert(columns[c].name);
                    }
                    if (on_point) on_point(r);
                },
                &stop_flag());
        },
        [&report] { report.flush(); });
    return out;
}

}  // namespace vi::python
