// sweep: `vibroimpact sweep` in-process; its table is built from the same CSV rows the command
// writes, so the arrays equal the command's sweep.csv cell for cell.

#include <algorithm>
#include <chrono>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "point_rows.hpp"
#include "io/number_text.hpp"
#include "model/input_error.hpp"
#include "model/parallel_for.hpp"
#include "study/analyses/sweep_analyses.hpp"
#include "sweep/columns.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"
#include "sweep/table.hpp"

namespace vi::python {
namespace {

// A value spec of sweep(): "start:stop:count" (or any SPEC of --set) as is, a number, or numbers
// written as a --set list with the shortest text that reads back the same double.
std::string spec_of(const std::string& path, const py::handle& v) {
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v)) return round_trip_text(v.cast<double>());
    if (!py::isinstance<py::iterable>(v)) throw InputError("--set " + path + ": give a SPEC string, a number or a list of numbers");
    std::string spec;
    for (const py::handle x : v) {
        if (!spec.empty()) spec += ',';
        spec += round_trip_text(x.cast<double>());
    }
    return spec;
}

// {path: spec} in grid order (first slowest), or a list of "PATH=SPEC" as on the command line.
std::vector<std::string> settings_of(const py::object& values) {
    std::vector<std::string> sets;
    if (py::isinstance<py::dict>(values)) {
        for (const auto& [k, v] : values.cast<py::dict>()) {
            const std::string path = py::str(k).cast<std::string>();
            sets.push_back(path + "=" + spec_of(path, v));
        }
    } else {
        for (const py::handle s : values) sets.push_back(py::str(s).cast<std::string>());
    }
    if (sets.empty()) throw InputError("sweep: no value to vary (give {path: spec})");
    return sets;
}

SweepAnalysis analysis_of(const std::string& name) {
    for (SweepAnalysis a : kSweepAnalyses) {
        if (name == sweep_analysis_name(a)) return a;
    }
    throw InputError("analysis: \"" + name + "\" is none of " + sweep_analysis_names(", "));
}

py::dict sweep(const Case& base, const py::object& values, const std::string& analysis, int modes,
               const std::string& support_model, int threads, double point_timeout,
               const std::optional<std::string>& progress_mode, double progress_interval) {
    const SweepGrid grid = parse_sweep_grid(settings_of(values), base);
    SweepSettings settings;
    settings.analysis = analysis_of(analysis);
    if (modes < 1 || modes > 100) throw InputError("modes: must be 1 to 100 (got " + std::to_string(modes) + ")");
    settings.modes = modes;
    settings.support_model = support_model_of(support_model);
    if (!(point_timeout >= 0.0)) throw InputError("point_timeout: must be 0 (none) or positive seconds");
    settings.point_timeout = point_timeout;
    if (threads < 0) throw InputError("threads: must be 0 (every CPU this process may use) or more");
    const int workers = resolve_thread_count(threads);
    settings = with_study_analyses(settings);
    check_sweep_analysis(base, settings);
    settings.supports = static_cast<int>(base.supports.size());
    const std::vector<SweepColumn> columns = sweep_result_columns(settings.analysis, settings.modes, settings.supports);

    // Integer columns: whole-number paths, and results that are counts.
    std::set<std::string> integer_columns;
    for (const SweepAxis& a : grid.axes()) {
        if (is_integer_path(a.path)) integer_columns.insert(case_path_column(a.path));
    }
    SweepRunInfo info;
    const auto t0 = std::chrono::steady_clock::now();
    PointRows points = run_point_rows(base, grid, settings, workers, columns, "sweep", "points", progress_mode,
                                      progress_interval, [&info](const SweepPointResult& r) {
                                          ++info.points_done;
                                          if (!r.ok()) info.failures.emplace_back(r.index, r.status);
                                      });
    integer_columns.merge(points.integer_columns);
    info.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::string csv = sweep_csv_header(grid, columns) + "\n";
    for (const std::string& row : points.rows) csv += row + "\n";
    std::sort(info.failures.begin(), info.failures.end());
    info.case_path = base.origin.file;
    info.case_name = base.name;
    info.settings = settings;
    info.columns = columns;
    info.failed = info.failures.size();
    info.computed_this_run = info.points_done;
    info.threads = workers;
    py::dict out;
    out["table"] = csv_columns(csv, integer_columns);
    out["summary"] = json_value(sweep_summary_json(grid, info).dump());
    return out;
}

}  // namespace

void bind_sweep(py::module_& m) {
    m.def("sweep", &sweep, py::arg("case"), py::arg("values"), py::arg("analysis") = "simulate", py::arg("modes") = 3,
          py::arg("support_model") = "pin", py::arg("threads") = 0, py::arg("point_timeout") = 60.0,
          py::arg("progress") = py::none(), py::arg("progress_interval") = 10.0,
          "A sweep (`vibroimpact sweep --set PATH=SPEC ...`): values is {path: spec} (first path slowest) where "
          "spec is a --set SPEC string ('0.6:1:5', 'log:1e-7:1e-5:9', '1,2,3'), a number or a list of numbers. "
          "Returns {'table': {column: array} as sweep.csv, 'summary': dict as sweep.json}");
}

}  // namespace vi::python
