// paper: `vibroimpact paper` in-process: the claims and the figures' data, and with a folder the
// command's files (figures drawn with gnuplot, report.html).

#include <chrono>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "io/output_files.hpp"
#include "io/units.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "plot/figure_gnuplot.hpp"
#include "study/paper/claims.hpp"
#include "study/paper/figures.hpp"
#include "study/paper/report.hpp"
#include "study/paper/study.hpp"

namespace vi::python {
namespace {

int checked_count(const char* name, int v) {
    if (v < 2 || v > 100000) throw InputError(std::string(name) + ": must be 2 to 100000 (got " + std::to_string(v) + ")");
    return v;
}

py::dict paper(const std::string& out, int positions, int modal_positions, int prestress_points, const std::string& scan_horizon,
               const std::string& examples, int threads, const std::string& gnuplot,
               const std::optional<std::string>& progress_mode, double progress_interval) {
    PaperStudyOptions so;
    so.positions = checked_count("positions", positions);
    so.modal_positions = checked_count("modal_positions", modal_positions);
    so.prestress_points = checked_count("prestress_points", prestress_points);
    try {
        so.position_horizon = parse_quantity(scan_horizon, Dimension::time);
    } catch (const std::invalid_argument& e) {
        throw InputError("scan_horizon: " + std::string(e.what()));
    }
    if (!(so.position_horizon > 0.0)) throw InputError("scan_horizon: must be positive");
    if (threads < 0) throw InputError("threads: must be 0 (every CPU this process may use) or more");
    so.threads = threads;
    std::optional<std::string> gnuplot_exe;
    if (!out.empty()) {
        gnuplot_exe = find_gnuplot(gnuplot);
        if (!gnuplot_exe) throw InputError("gnuplot: '" + gnuplot + "' not found; the figures of out need it (Debian: gnuplot-nox)");
    }
    so.cases = load_paper_cases(examples);
    // As the command: the study's jobs counted, and a line as each part of it ends.
    const PythonProgress out_progress(progress_mode, progress_interval);
    Progress jobs("paper", "jobs", 0, 0, out_progress.style(), out_progress.interval_s(), false, out_progress.sink());
    const auto t0 = std::chrono::steady_clock::now();
    so.progress = [&jobs, t0](const std::string& line) {
        char at[32];
        std::snprintf(at, sizeof at, "[%5.1f s] ", seconds_since(t0));
        jobs.say("paper: " + std::string(at) + line);
    };
    so.jobs_done = [&jobs](std::size_t done, std::size_t total) {
        if (done == 0) {
            jobs.set_total(total);
        } else {
            jobs.advance();
        }
    };
    std::optional<PaperStudy> study;
    std::vector<Claim> claims;
    std::vector<FigureSpec> figures;
    OutputFiles files;
    run_released(
        [&] {
            {
                const FinishProgress finish{jobs};
                const ProgressTicker ticker(jobs);
                study.emplace(run_paper_study(so));
            }
            claims = paper_claims(*study);
            figures = paper_figures(*study);
            if (!gnuplot_exe) return;
            const std::vector<RenderedFigure> rendered = render_figures(*gnuplot_exe, figures, study->timing.threads);
            ReportRun run;
            run.version = "vibroimpact " VI_VERSION;
            run.command = "vibroimpact.paper(out='" + out + "')";
            files = paper_output_files(*study, claims, figures, rendered, run);
            write_output_files(out, files);
        },
        [&out_progress] { out_progress.flush(); });
    py::dict figure_data;
    for (const FigureSpec& f : figures) {
        py::dict tables;
        for (const auto& [name, csv] : f.data) tables[py::str(name.substr(0, name.rfind('.')))] = csv_columns(csv);
        figure_data[py::str(f.name)] = tables;
    }
    py::dict result;
    result["claims"] = json_value(claims_json(claims));
    result["figures"] = figure_data;
    result["timing"] = py::dict(py::arg("wall_s") = study->timing.wall_s, py::arg("threads") = study->timing.threads,
                                py::arg("transients") = study->timing.transients);
    return result;
}

}  // namespace

void bind_paper(py::module_& m) {
    m.def("paper", &paper, py::arg("out") = "", py::arg("positions") = 50, py::arg("modal_positions") = 100,
          py::arg("prestress_points") = 26, py::arg("scan_horizon") = "500 us", py::arg("examples") = "",
          py::arg("threads") = 0, py::arg("gnuplot") = "gnuplot", py::arg("progress") = py::none(),
          py::arg("progress_interval") = 10.0,
          "`vibroimpact paper`: {'claims': claims.json, 'figures': {figure: {csv: columns}}, 'timing': dict}; "
          "with out, the command's files written there");
}

}  // namespace vi::python
