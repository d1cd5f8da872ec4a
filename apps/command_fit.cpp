// `vibroimpact fit CASE (--data FILE | --features FILE) --fit PATH[=LOW:HIGH] ...`: case values
// estimated from a measured trajectory of the watched point or from measured features, with their
// uncertainty (docs/calibration.md).

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "calibration/fit_run.hpp"
#include "commands.hpp"
#include "figure_output.hpp"
#include "fit_report.hpp"
#include "progress.hpp"
#include "io/case_reader.hpp"
#include "io/number_text.hpp"
#include "io/output_files.hpp"
#include "model/input_error.hpp"
#include "model/parallel_for.hpp"
#include "model/run_control.hpp"
#include "plot/figure_gnuplot.hpp"
#include "stop_signals.hpp"

namespace vi::cli {
namespace {

struct FitCommandOptions {
    std::string case_path, data, features, column;
    std::vector<std::string> fit;
    bool time_shift = false, scale = false, two_stage = false;
    std::string time_shift_range, scale_range;
    int max_iterations = 50, starts = 1, threads = 0;
    std::string out = "out/fit";
    std::string gnuplot = "gnuplot";
    bool json = false;
    ProgressSettings progress;
};

std::string command_line(const FitCommandOptions& o) {
    std::string command = "vibroimpact fit " + o.case_path;
    command += o.data.empty() ? " --features " + o.features : " --data " + o.data;
    for (const std::string& f : o.fit) command.append(" --fit '").append(f).append("'");
    if (o.time_shift) command += " --time-shift" + (o.time_shift_range.empty() ? "" : " --time-shift-range " + o.time_shift_range);
    if (o.scale) command += " --scale" + (o.scale_range.empty() ? "" : " --scale-range " + o.scale_range);
    if (o.starts > 1) command += " --starts " + std::to_string(o.starts);
    if (o.two_stage) command += " --two-stage";
    return command;
}

int finish(const FitCommandOptions& o, const FitRun& run, const std::string& gnuplot) {
    nlohmann::json j = run.json;
    j["command"] = command_line(o);
    OutputFiles files;
    files["fit_residuals.csv"] = run.residuals_csv;
    files["fit.json"] = j.dump(2) + "\n";
    const FigureSpec figure = run.trajectory ? trajectory_figure(*run.trajectory, run.shown()) : feature_figure(*run.features, run.shown());
    const std::optional<std::string> figure_failed = write_with_figures(o.out, std::move(files), {figure}, gnuplot);
    if (o.json) {
        std::printf("%s\n", j.dump(2).c_str());
    } else {
        std::printf("%sWritten to %s/\n", run.text.c_str(), o.out.c_str());
    }
    const std::string figure_note =
        figure_failed ? "; the figure was not drawn (" + *figure_failed + "), fit.json and fit_residuals.csv are written" : "";
    for (const FitResult& r : run.results) {
        if (!r.converged) {
            std::fprintf(stderr, "vibroimpact: fit: did not converge (%s); fit.json holds the last estimate%s\n", r.message.c_str(),
                         figure_note.c_str());
            return kExitFailure;
        }
    }
    if (figure_failed) {
        std::fprintf(stderr, "vibroimpact: fit: the figure was not drawn (%s); fit.json and fit_residuals.csv are written in %s\n",
                     figure_failed->c_str(), o.out.c_str());
        return kExitFailure;
    }
    return kExitOk;
}

}  // namespace

CommandBody add_fit_command(CLI::App& app) {
    auto opt = std::make_shared<FitCommandOptions>();
    CLI::App* sub = app.add_subcommand("fit", "Case values estimated from a measured trajectory or measured features, with "
                                              "standard errors and 95 % intervals");
    sub->add_option("case", opt->case_path, "Case file (TOML): the model and the start of every fitted value")->required();
    auto* data = sub->add_option("--data", opt->data, "CSV trajectory: t_s, the measured column and optionally sigma "
                                                      "(docs/calibration.md)");
    auto* features = sub->add_option("--features", opt->features, "CSV features: name, value, sigma per row (f1_hz, q1, "
                                                                  "T_s, T1_s, T2_s, Tp_s, y_max_m, z_max, "
                                                                  "impact1_peak_force_n, closing_time_s, V_PI_V)");
    data->excludes(features);
    features->excludes(data);
    sub->add_option("--fit", opt->fit, "PATH or PATH=LOW:HIGH (SI units), as --set of sweep (repeat for more)")->required();
    sub->add_option("--column", opt->column, "The measured column: the case's watched point, <name>_m (default) or "
                                             "<name>_velocity_m_s, name tip (free end), midspan (held at both ends) or point");
    sub->add_flag("--time-shift", opt->time_shift, "Fit the record's time offset t0 (the model read at t - t0), a nuisance "
                                                   "parameter");
    sub->add_option("--time-shift-range", opt->time_shift_range, "LOW:HIGH bounds of t0 (s or with a time unit; default "
                                                                 "+-10 % of the record)");
    sub->add_flag("--scale", opt->scale, "Fit the measurement's gain g (data = g * model), a nuisance parameter");
    sub->add_option("--scale-range", opt->scale_range, "LOW:HIGH bounds of g (default 0.5:2)");
    sub->add_option("--starts", opt->starts, "Starting points: the case's values, then a Halton sample within the bounds")
        ->check(CLI::Range(1, 1000))->capture_default_str();
    sub->add_option("--threads,-j", opt->threads, "Threads for the starts (0: every CPU this process may use)")
        ->check(CLI::Range(0, 4096))->capture_default_str();
    sub->add_flag("--two-stage", opt->two_stage, "Fit the non-contact values to the record before the first impact, then "
                                                 "the contact values (supports[...]) to the whole record");
    sub->add_option("--max-iterations", opt->max_iterations, "Levenberg-Marquardt iterations at most (per start)")
        ->check(CLI::Range(1, 10000))->capture_default_str();
    sub->add_option("--out,-o", opt->out, "Folder for fit.json, fit_residuals.csv and the figure")->capture_default_str();
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (name on PATH or path)")->capture_default_str();
    sub->add_flag("--json", opt->json, "Print fit.json on stdout instead of text");
    add_progress_options(*sub, opt->progress);

    return [opt]() {
        const FitCommandOptions& o = *opt;
        const FitRequest request{o.fit, o.data, o.features, o.column, o.time_shift, o.time_shift_range,
                                 o.scale, o.scale_range, o.two_stage};
        check_fit_request(request);
        const ProgressStyle style = progress_style(o.progress);
        const std::string gnuplot = require_gnuplot(o.gnuplot, "the fit figure");
        const Case c = read_case_file(o.case_path);
        fit_parameters(c, request);  // the settings refused before the progress line starts
        // Iterations of the budget: a start that converges early counts the rest of its share as done,
        // outside the rate (so the time left is that of the budget at the rate of real iterations).
        const int budget = (o.two_stage ? 2 : 1) * o.starts * o.max_iterations;
        Progress progress("fit", "iterations", static_cast<std::size_t>(budget), 0, style, o.progress.interval_s, true);
        const FitOptions fo{o.max_iterations, o.starts, o.threads,
                            [&progress](int iterations, int unused) {
                                progress.advance(static_cast<std::size_t>(iterations));
                                progress.skip(static_cast<std::size_t>(unused));
                            }};
        const FitRun run = [&] {
            const ProgressTicker ticker(progress);
            return run_fit(c, o.case_path, request, fo);
        }();
        progress.finish();
        return finish(o, run, gnuplot);
    };
}

}  // namespace vi::cli
