// `vibroimpact fit CASE --data FILE --fit PATH[=LOW:HIGH] ...`: case values estimated from a measured
// tip trajectory, with their uncertainty (docs/calibration.md).

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "calibration/trajectory_fit.hpp"
#include "commands.hpp"
#include "figure_output.hpp"
#include "io/case_reader.hpp"
#include "io/number_text.hpp"
#include "io/output_files.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "plot/figure_gnuplot.hpp"
#include "stop_signals.hpp"

namespace vi::cli {
namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json fit_json(const std::vector<FitParameter>& params, const MeasuredTrajectory& data, const FitResult& r,
                        const std::string& command) {
    nlohmann::json j;
    j["command"] = command;
    j["data"] = {{"file", data.file}, {"column", data.column}, {"samples", data.t.size()}};
    j["converged"] = r.converged;
    j["message"] = r.message;
    j["iterations"] = r.iterations;
    j["simulations"] = r.simulations;
    j["rms_residual"] = r.rms;
    j["noise"] = r.sigma_from_residuals ? nlohmann::json{{"from", "residuals"}, {"sigma", r.sigma}}
                                        : nlohmann::json{{"from", "data sigma column"}};
    for (std::size_t i = 0; i < params.size(); ++i) {
        nlohmann::json p;
        p["path"] = params[i].path.text();
        p["start"] = params[i].start;
        p["estimate"] = r.estimate[i];
        p["std_error"] = number_or_null(r.std_error[i]);
        p["ci95"] = {number_or_null(r.ci_low[i]), number_or_null(r.ci_high[i])};
        p["determined"] = r.undetermined[i].empty();
        if (!r.undetermined[i].empty()) p["why_undetermined"] = r.undetermined[i];
        j["parameters"].push_back(p);
    }
    for (Eigen::Index a = 0; a < r.correlation.rows(); ++a) {
        nlohmann::json row = nlohmann::json::array();
        for (Eigen::Index b = 0; b < r.correlation.cols(); ++b) row.push_back(number_or_null(r.correlation(a, b)));
        j["correlation"].push_back(row);
    }
    return j;
}

std::string residuals_csv(const MeasuredTrajectory& data, const FitResult& r) {
    std::string text = "t_s,data,model,residual\n";
    for (std::size_t k = 0; k < data.t.size(); ++k) {
        text.append(round_trip_text(data.t[k])).append(",").append(round_trip_text(data.value[k])).append(",");
        text.append(round_trip_text(r.model[k])).append(",").append(round_trip_text(r.residual[k])).append("\n");
    }
    return text;
}

FigureSpec fit_figure(const MeasuredTrajectory& data, const FitResult& r) {
    FigureSpec f;
    f.name = "fit";
    f.title = "Measured and fitted " + data.column;
    f.caption = "The data (points) and the fitted model (line) against time, and the residual (model - data) below.";
    f.data = {{"fit.csv", residuals_csv(data, r)}};
    f.height = 800;
    f.plot = "set datafile separator ','\nset multiplot layout 2,1\nset key top right\nset xlabel 't [us]'\nset ylabel " +
             gp_quote(data.column) + " noenhanced\nplot 'fit.csv' using ($1*1e6):2 every ::1 with points pt 7 ps 0.4 title 'data', "
             "'' using ($1*1e6):3 every ::1 with lines lw 2 title 'model'\nset ylabel 'residual' noenhanced\n"
             "plot 'fit.csv' using ($1*1e6):4 every ::1 with lines title 'model - data'\nunset multiplot\n";
    return f;
}

}  // namespace

CommandBody add_fit_command(CLI::App& app) {
    struct Options {
        std::string case_path, data, column = "tip_m";
        std::vector<std::string> fit;
        int max_iterations = 50;
        std::string out = "out/fit";
        std::string gnuplot = "gnuplot";
        bool json = false;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("fit", "Case values estimated from a measured tip trajectory, with standard errors and 95 % intervals");
    sub->add_option("case", opt->case_path, "Case file (TOML): the model and the start of every fitted value")->required();
    sub->add_option("--data", opt->data, "CSV: t_s, the measured column and optionally sigma (docs/calibration.md)")->required();
    sub->add_option("--fit", opt->fit, "PATH or PATH=LOW:HIGH (SI units), as --set of sweep (repeat for more)")->required();
    sub->add_option("--column", opt->column, "The measured column: tip_m or tip_velocity_m_s")
        ->check(CLI::IsMember({"tip_m", "tip_velocity_m_s"}))->capture_default_str();
    sub->add_option("--max-iterations", opt->max_iterations, "Levenberg-Marquardt iterations at most")
        ->check(CLI::Range(1, 10000))->capture_default_str();
    sub->add_option("--out,-o", opt->out, "Folder for fit.json, fit_residuals.csv and the figure")->capture_default_str();
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (name on PATH or path)")->capture_default_str();
    sub->add_flag("--json", opt->json, "Print fit.json on stdout instead of text");

    return [opt]() {
        const std::string gnuplot = require_gnuplot(opt->gnuplot, "the fit figure");
        const Case c = read_case_file(opt->case_path);
        std::vector<FitParameter> params;
        for (const std::string& f : opt->fit) params.push_back(parse_fit_parameter(f, c));
        for (std::size_t i = 0; i < params.size(); ++i) {
            for (std::size_t k = 0; k < i; ++k) {
                if (params[k].path == params[i].path) throw InputError("--fit " + params[i].setting + ": " + params[i].path.text() + " is fitted twice");
            }
        }
        const MeasuredTrajectory data = read_measured_trajectory(opt->data, opt->column, params.size() + 1);
        FitResult r;
        try {
            r = fit_trajectory(c, params, data, FitOptions{opt->max_iterations});
        } catch (const InputError& e) {
            throw locate_in_case(c, e);
        }
        std::string command = "vibroimpact fit " + opt->case_path + " --data " + opt->data;
        for (const std::string& f : opt->fit) command.append(" --fit '").append(f).append("'");
        const nlohmann::json j = fit_json(params, data, r, command);
        OutputFiles files;
        files["fit.json"] = j.dump(2) + "\n";
        files["fit_residuals.csv"] = residuals_csv(data, r);
        const std::vector<FigureSpec> figures = {fit_figure(data, r)};
        write_with_figures(opt->out, std::move(files), figures, gnuplot);
        if (opt->json) {
            std::printf("%s\n", j.dump(2).c_str());
        } else {
            std::printf("Fit of %s to %s (%zu samples): %s after %d iterations, %d simulations; rms residual %s\n",
                        opt->case_path.c_str(), data.file.c_str(), data.t.size(), r.converged ? "converged" : "NOT converged",
                        r.iterations, r.simulations, round_trip_text(r.rms).c_str());
            for (std::size_t i = 0; i < params.size(); ++i) {
                if (r.undetermined[i].empty()) {
                    std::printf("  %s = %.6g +- %.3g (95 %%: %.6g .. %.6g)\n", params[i].path.text().c_str(), r.estimate[i],
                                r.std_error[i], r.ci_low[i], r.ci_high[i]);
                } else {
                    std::printf("  %s = %.6g: NOT determined by the data (%s)\n", params[i].path.text().c_str(), r.estimate[i],
                                r.undetermined[i].c_str());
                }
            }
            std::printf("Written to %s/\n", opt->out.c_str());
        }
        if (!r.converged) {
            std::fprintf(stderr, "vibroimpact: fit: did not converge (%s); fit.json holds the last estimate\n", r.message.c_str());
            return kExitFailure;
        }
        return kExitOk;
    };
}

}  // namespace vi::cli
