// fit and optimize: `vibroimpact fit` and `vibroimpact optimize` in-process, their results the files
// the commands write (fit.json and fit_residuals.csv; optimize.json and evaluations.csv).

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "calibration/fit_run.hpp"
#include "design/optimize_output.hpp"
#include "design/optimizer.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"
#include "study/analyses/design_setup.hpp"

namespace vi::python {
namespace {

py::dict fit(const Case& c, const std::vector<std::string>& parameters, const std::string& data,
             const std::string& features, const std::string& column, bool time_shift, const std::string& time_shift_range,
             bool scale, const std::string& scale_range, bool two_stage, int starts, int max_iterations, int threads,
             const std::optional<std::string>& progress_mode, double progress_interval) {
    if (starts < 1 || starts > 1000) throw InputError("starts: must be 1 to 1000 (got " + std::to_string(starts) + ")");
    if (max_iterations < 1 || max_iterations > 10000) {
        throw InputError("max_iterations: must be 1 to 10000 (got " + std::to_string(max_iterations) + ")");
    }
    if (threads < 0) throw InputError("threads: must be 0 (every CPU this process may use) or more");
    const FitRequest request{parameters, data, features, column, time_shift, time_shift_range, scale, scale_range, two_stage};
    check_fit_request(request);
    fit_parameters(c, request);  // the settings refused before the progress report starts
    const PythonProgress out_progress(progress_mode, progress_interval);
    // Iterations of the budget, as the command counts them: a start that converges early counts the
    // rest of its share as done, outside the rate.
    const int budget = (two_stage ? 2 : 1) * starts * max_iterations;
    Progress progress("fit", "iterations", static_cast<std::size_t>(budget), 0, out_progress.style(),
                      out_progress.interval_s(), true, out_progress.sink());
    const FitOptions options{max_iterations, starts, threads, [&progress](int iterations, int unused) {
                                 progress.advance(static_cast<std::size_t>(iterations));
                                 progress.skip(static_cast<std::size_t>(unused));
                             }};
    std::optional<FitRun> run;
    run_released(
        [&] {
            const FinishProgress finish{progress};
            const ProgressTicker ticker(progress);
            run.emplace(run_fit(c, c.origin.file, request, options));
        },
        [&out_progress] { out_progress.flush(); });
    py::dict out;
    out["fit"] = json_value(run->json.dump());
    out["fit_residuals"] = csv_columns(run->residuals_csv);
    out["text"] = py::str(run->text);
    return out;
}

py::dict optimize(const Case& c, const std::vector<std::string>& vary, const std::string& minimize,
                  const std::string& maximize, const std::vector<std::string>& constraints, const std::string& analysis,
                  int modes, int max_evals, int global_evals, int threads, double point_timeout,
                  const std::optional<std::string>& progress_mode, double progress_interval) {
    if (max_evals < 2 || max_evals > 100000) throw InputError("max_evals: must be 2 to 100000 (got " + std::to_string(max_evals) + ")");
    if (global_evals < 0 || global_evals >= max_evals) {
        throw InputError("global_evals: must be 0 (half) or below max_evals " + std::to_string(max_evals) +
                         " (the local stage needs one at least)");
    }
    if (threads < 0) throw InputError("threads: must be 0 (every CPU this process may use) or more");
    const DesignProblem p = design_problem(c, {vary, minimize, maximize, constraints, analysis, modes, point_timeout});
    OptimizeOptions o;
    o.max_evaluations = max_evals;
    o.global_evaluations = global_evals;
    o.threads = threads;
    const PythonProgress out_progress(progress_mode, progress_interval);
    // Designs used of max_evals (the search may end sooner), and the best objective so far.
    Progress progress("optimize", "designs", static_cast<std::size_t>(max_evals), 0, out_progress.style(),
                      out_progress.interval_s(), true, out_progress.sink());
    const std::string& quantity = p.columns[p.objective].name;
    OptimizeResult r;
    const auto t0 = std::chrono::steady_clock::now();
    run_released(
        [&] {
            const FinishProgress finish{progress};
            const ProgressTicker ticker(progress);
            r = optimize_design(p, o, [&](const DesignEvaluation& e) {
                progress.advance();
                if (e.best) progress.set_note("best " + quantity + " " + significant(*e.best, 6));
            });
        },
        [&out_progress] { out_progress.flush(); });
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    nlohmann::json j = optimize_result_json(p, r, "vibroimpact.optimize");
    j["run"] = optimize_run_json(r, wall_s);
    py::dict out;
    out["optimize"] = json_value(j.dump());
    out["evaluations"] = csv_columns(evaluations_csv(p, r), {"index", "feasible"});
    return out;
}

}  // namespace

void bind_design(py::module_& m) {
    m.def("fit", &fit, py::arg("case"), py::arg("parameters"), py::arg("data") = "", py::arg("features") = "",
          py::arg("column") = "", py::arg("time_shift") = false, py::arg("time_shift_range") = "", py::arg("scale") = false,
          py::arg("scale_range") = "", py::arg("two_stage") = false, py::arg("starts") = 1, py::arg("max_iterations") = 50,
          py::arg("threads") = 0, py::arg("progress") = py::none(), py::arg("progress_interval") = 10.0,
          "`vibroimpact fit`: {'fit': fit.json, 'fit_residuals': columns, 'text': the summary}");
    m.def("optimize", &optimize, py::arg("case"), py::arg("vary"), py::arg("minimize") = "", py::arg("maximize") = "",
          py::arg("constraints") = std::vector<std::string>{}, py::arg("analysis") = "simulate", py::arg("modes") = 3,
          py::arg("max_evals") = 100, py::arg("global_evals") = 0, py::arg("threads") = 0, py::arg("point_timeout") = 60.0,
          py::arg("progress") = py::none(), py::arg("progress_interval") = 10.0, "`vibroimpact optimize`: {'optimize': optimize.json, 'evaluations': columns}");
}

}  // namespace vi::python
