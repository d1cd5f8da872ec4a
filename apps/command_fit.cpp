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

#include "calibration/feature_fit.hpp"
#include "calibration/trajectory_fit.hpp"
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
    std::string out;
    std::string gnuplot = "gnuplot";
    bool json = false;
    ProgressSettings progress;
};

// A case key's error located in the case file; an error that already names its file or option as is.
InputError in_case(const Case& c, const InputError& e, const std::string& data_file) {
    const std::string what = e.what();
    const std::string key = what.substr(0, what.find(": "));
    if (key.find(':') != std::string::npos || key.rfind("-", 0) == 0 || key == data_file) return e;
    return locate_in_case(c, e);
}

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

int finish(const FitCommandOptions& o, const nlohmann::json& j, OutputFiles files, const std::vector<FigureSpec>& figures,
           const std::string& gnuplot, const std::string& text, const std::vector<const FitResult*>& results) {
    files["fit.json"] = j.dump(2) + "\n";
    const std::optional<std::string> figure_failed = write_with_figures(o.out, std::move(files), figures, gnuplot);
    if (o.json) {
        std::printf("%s\n", j.dump(2).c_str());
    } else {
        std::printf("%sWritten to %s/\n", text.c_str(), o.out.c_str());
    }
    const std::string figure_note =
        figure_failed ? "; the figure was not drawn (" + *figure_failed + "), fit.json and fit_residuals.csv are written" : "";
    for (const FitResult* r : results) {
        if (!r->converged) {
            std::fprintf(stderr, "vibroimpact: fit: did not converge (%s); fit.json holds the last estimate%s\n", r->message.c_str(),
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

int run_features(const FitCommandOptions& o, const Case& c, const std::vector<FitParameter>& params, const std::string& gnuplot,
                 const FitOptions& fo, Progress& progress) {
    if (o.time_shift || o.scale || o.two_stage) {
        throw InputError(std::string(o.time_shift ? "--time-shift" : o.scale ? "--scale" : "--two-stage") +
                         ": works on a trajectory (--data), not on features");
    }
    const MeasuredFeatures data = read_measured_features(o.features);
    check_features(c, data);
    FitResult r;
    try {
        r = fit_features(c, params, data, fo);
    } catch (const InputError& e) {
        throw in_case(c, e, o.features);
    }
    progress.finish();
    nlohmann::json j = fit_result_json(params, r);
    j["command"] = command_line(o);
    j["features"] = {{"file", data.file}, {"count", data.features.size()}};
    j["rms_normalized_residual"] = r.rms;
    for (std::size_t k = 0; k < data.features.size(); ++k) {
        const MeasuredFeature& f = data.features[k];
        j["feature_residuals"].push_back({{"name", f.name}, {"value", f.value}, {"sigma", f.sigma}, {"model", r.model[k]},
                                          {"normalized", r.residual[k] / f.sigma}});
    }
    std::string text;
    {
        char head[512];
        std::snprintf(head, sizeof head, "Fit of %s to %s (%zu features): %s after %d iterations, %d simulations; rms of "
                      "(model - value) / sigma %.3g\n", o.case_path.c_str(), data.file.c_str(), data.features.size(),
                      r.converged ? "converged" : "NOT converged", r.iterations, r.simulations, r.rms);
        text = head;
    }
    text += fit_result_text(params, r);
    OutputFiles files;
    files["fit_residuals.csv"] = feature_residuals_csv(data, r);
    return finish(o, j, std::move(files), {feature_figure(data, r)}, gnuplot, text, {&r});
}

int run_trajectory(const FitCommandOptions& o, const Case& c, std::vector<FitParameter> params, const std::string& gnuplot,
                   const FitOptions& fo, Progress& progress) {
    const std::string column = o.column.empty() ? watched_point_name(c) + "_m" : o.column;
    check_trajectory_column(c, column);
    std::size_t extra = (o.time_shift ? 1 : 0) + (o.scale ? 1 : 0);
    const MeasuredTrajectory data = read_measured_trajectory(o.data, column, params.size() + extra + 1);
    if (o.time_shift) params.push_back(time_shift_parameter(data.t.back() - data.t.front(), o.time_shift_range));
    if (o.scale) params.push_back(scale_parameter(o.scale_range));
    nlohmann::json j;
    std::string text;
    const FitResult* shown = nullptr;
    std::vector<const FitResult*> results;
    TwoStageFit two;
    FitResult one;
    try {
        if (o.two_stage) {
            two = fit_two_stage(c, params, data, fo);
        } else {
            one = fit_trajectory(c, params, data, fo);
        }
    } catch (const InputError& e) {
        throw in_case(c, e, o.data);
    }
    progress.finish();
    if (o.two_stage) {
        std::vector<FitParameter> p1, p2;
        for (std::size_t i : two.stage1_params) p1.push_back(params[i]);
        for (std::size_t i : two.stage2_params) p2.push_back(params[i]);
        nlohmann::json s1 = fit_result_json(p1, two.stage1), s2 = fit_result_json(p2, two.stage2);
        s1["samples"] = two.split_samples;
        s1["record_end_s"] = two.split_time;
        s2["samples"] = data.t.size();
        for (double e : two.stage2_conditional_std_error) {
            s2["std_error_given_stage1"].push_back(std::isfinite(e) ? nlohmann::json(e) : nlohmann::json(nullptr));
        }
        j["two_stage"] = {{"first_impact_s", two.split_time}, {"stage1", s1}, {"stage2", s2}};
        j["converged"] = two.stage1.converged && two.stage2.converged;
        j["estimate"] = nlohmann::json::object();
        for (std::size_t i = 0; i < params.size(); ++i) j["estimate"][params[i].name()] = two.estimate[i];
        shown = &two.stage2;
        results = {&two.stage1, &two.stage2};
        char head[512];
        std::snprintf(head, sizeof head, "Two-stage fit of %s to %s (%zu samples, %zu before the first impact at %.6g us):\n",
                      o.case_path.c_str(), data.file.c_str(), data.t.size(), two.split_samples, two.split_time * 1e6);
        text = head;
        const auto stage = [&](const char* name, const FitResult& r, const std::vector<FitParameter>& p) {
            char line[256];
            std::snprintf(line, sizeof line, "Stage %s: %s after %d iterations, %d simulations\n", name,
                          r.converged ? "converged" : "NOT converged", r.iterations, r.simulations);
            text += line + fit_result_text(p, r);
        };
        stage("1 (before the first impact)", two.stage1, p1);
        stage("2 (contact parameters, whole record)", two.stage2, p2);
    } else {
        j = fit_result_json(params, one);
        shown = &one;
        results = {&one};
        char head[512];
        std::snprintf(head, sizeof head, "Fit of %s to %s (%zu samples): %s after %d iterations, %d simulations; rms residual %s\n",
                      o.case_path.c_str(), data.file.c_str(), data.t.size(), one.converged ? "converged" : "NOT converged",
                      one.iterations, one.simulations, round_trip_text(one.rms).c_str());
        text = head + fit_result_text(params, one);
    }
    j["command"] = command_line(o);
    j["data"] = {{"file", data.file}, {"column", data.column}, {"samples", data.t.size()}};
    j["rms_residual"] = shown->rms;
    j["noise"] = shown->sigma_from_residuals ? nlohmann::json{{"from", "residuals"}, {"sigma", shown->sigma}}
                                             : nlohmann::json{{"from", "data sigma column"}};
    OutputFiles files;
    files["fit_residuals.csv"] = trajectory_residuals_csv(data, *shown);
    return finish(o, j, std::move(files), {trajectory_figure(data, *shown)}, gnuplot, text, results);
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
    sub->add_option("--out,-o", opt->out, "Folder for fit.json, fit_residuals.csv and the figure (required: a fit's result is these files)")
        ->required();
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (name on PATH or path)")->capture_default_str();
    sub->add_flag("--json", opt->json, "Print fit.json on stdout instead of text");
    add_progress_options(*sub, opt->progress);

    return [opt]() {
        const FitCommandOptions& o = *opt;
        if (o.data.empty() && o.features.empty()) throw InputError("--data or --features: one is required");
        if (!o.time_shift && !o.time_shift_range.empty()) throw InputError("--time-shift-range: needs --time-shift");
        if (!o.scale && !o.scale_range.empty()) throw InputError("--scale-range: needs --scale");
        if (!o.features.empty() && !o.column.empty()) throw InputError("--column: works on a trajectory (--data)");
        const ProgressStyle style = progress_style(o.progress);
        const std::string gnuplot = require_gnuplot(o.gnuplot, "the fit figure");
        const Case c = read_case_file(o.case_path);
        std::vector<FitParameter> params;
        for (const std::string& f : o.fit) params.push_back(parse_fit_parameter(f, c));
        check_distinct(params);
        // Iterations of the budget: a start that converges early counts the rest of its share as done,
        // outside the rate (so the time left is that of the budget at the rate of real iterations).
        const int budget = (o.two_stage ? 2 : 1) * o.starts * o.max_iterations;
        Progress progress("fit", "iterations", static_cast<std::size_t>(budget), 0, style, o.progress.interval_s, true);
        const FitOptions fo{o.max_iterations, o.starts, o.threads,
                            [&progress](int iterations, int unused) {
                                progress.advance(static_cast<std::size_t>(iterations));
                                progress.skip(static_cast<std::size_t>(unused));
                            }};
        const ProgressTicker ticker(progress);
        return o.data.empty() ? run_features(o, c, params, gnuplot, fo, progress)
                              : run_trajectory(o, c, params, gnuplot, fo, progress);
    };
}

}  // namespace vi::cli
