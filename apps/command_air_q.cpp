// `vibroimpact air-q CASE [--out DIR]`: the quality factor of the first mode against air pressure, from
// the squeeze film's modal damping and from ring-down transients; a CSV and a figure.

#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "json_output.hpp"
#include "figure_output.hpp"
#include "progress.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "io/units.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "model/run_estimate.hpp"
#include "plot/figure_gnuplot.hpp"
#include "stop_signals.hpp"
#include "study/air/air_q.hpp"

namespace vi::cli {

CommandBody add_air_q_command(CLI::App& app) {
    struct AirQCommandOptions {
        std::string case_path;
        std::string out;
        bool json = false;
        std::string gap = "1 um";
        std::string gnuplot = "gnuplot";
        ProgressSettings progress;
    };
    auto opt = std::make_shared<AirQCommandOptions>();
    CLI::App* sub = app.add_subcommand("air-q", "Quality factor of mode 1 against air pressure (squeeze film), 1 atm to 1 Pa");
    sub->add_option("case", opt->case_path, "Case file (TOML): the beam; its [air], electrodes or [[films]] if any")
        ->required();
    sub->add_option("--out,-o", opt->out, "Folder for air_q.csv and the figure air_q.png/.svg (without it nothing is written)");
    sub->add_flag("--json", opt->json, "Print the table as JSON on stdout (the columns and rows of air_q.csv)");
    CLI::Option* gap_option =
        sub->add_option("--gap", opt->gap, "Film gap under the whole beam when the case has no electrode or film")
            ->capture_default_str();
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (name on PATH or path)")->capture_default_str();
    add_progress_options(*sub, opt->progress);

    return [opt, gap_option]() {
        const Case base = read_case_file(opt->case_path);
        if (gap_option->count() > 0 && (!base.electrodes.empty() || !base.films.empty())) {
            throw InputError("--gap " + opt->gap + ": the case's " + (base.electrodes.empty() ? "[[films]]" : "[[electrodes]]") +
                             " give the film and its gap; --gap is for a case without electrode or film");
        }
        double gap = 0.0;
        try {
            gap = parse_quantity(opt->gap, Dimension::length);
        } catch (const std::invalid_argument& e) {
            throw InputError(std::string("--gap: ") + e.what());
        }
        if (!(gap > 0.0)) throw InputError("--gap: must be positive");
        if (gap < 1.0 / kMagnitudeLimit || gap > kMagnitudeLimit) {
            throw InputError("--gap " + opt->gap + ": outside the magnitudes the tool computes with (1e-100 to 1e100 m; "
                             "docs/case-files.md, Limits)");
        }
        // The figure is a file: without --out nothing is drawn, and gnuplot is not needed.
        const std::string gnuplot = opt->out.empty() ? std::string() : require_gnuplot(opt->gnuplot, "the Q figure");
        const ProgressStyle style = progress_style(opt->progress);
        std::vector<AirQPoint> points;
        try {
            const Case c = air_q_case(base, gap);
            const std::vector<double> pressures = air_q_pressures();
            Progress progress("air-q", "pressures", pressures.size(), 0, style, opt->progress.interval_s);
            const ProgressTicker ticker(progress);
            for (double p : pressures) {
                check_run();
                points.push_back(air_q_point(c, p));
                progress.advance();
            }
        } catch (const InputError& e) {
            throw locate_in_case(base, e);
        }
        const FigureSpec figure = air_q_figure(points, base.name);
        const std::optional<std::string> figure_failed =
            opt->out.empty() ? std::nullopt : write_with_figures(opt->out, {}, {figure}, gnuplot);
        if (opt->json) {
            print_json(csv_as_json(figure.data.front().second, figure.data.front().first));
        } else {
            std::printf("%12s %10s %12s %10s %12s %12s\n", "pressure_Pa", "Kn", "mu_eff/mu", "sigma", "Q_modal", "Q_ringdown");
            for (const AirQPoint& x : points) {
                std::printf("%12.4g %10.4g %12.4g %10.4g %12.5g %12s\n", x.pressure, x.knudsen, x.viscosity_ratio,
                            x.squeeze_number, x.q_modal,
                            x.q_ringdown ? std::to_string(*x.q_ringdown).c_str() : "overdamped");
            }
        }
        if (figure_failed) {
            if (!opt->json) std::printf("Written to %s/ (air_q.csv, air_q.gp)\n", opt->out.c_str());
            std::fprintf(stderr, "vibroimpact: air-q: the figure was not drawn (%s); air_q.csv is written in %s\n",
                         figure_failed->c_str(), opt->out.c_str());
            return kExitFailure;
        }
        if (!opt->out.empty() && !opt->json) std::printf("Written to %s/ (air_q.csv, air_q.png, air_q.svg)\n", opt->out.c_str());
        return kExitOk;
    };
}

}  // namespace vi::cli
