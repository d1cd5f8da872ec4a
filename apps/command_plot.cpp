// `vibroimpact plot DIR`: draws what a run folder holds (a simulate, modes or sweep --out folder) as
// PNG and SVG figures, by default into DIR/plots.

#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "figure_output.hpp"
#include "io/output_files.hpp"
#include "model/run_control.hpp"
#include "plot/figure_gnuplot.hpp"
#include "stop_signals.hpp"
#include "study/run_plots/run_plots.hpp"

namespace vi::cli {

CommandBody add_plot_command(CLI::App& app) {
    struct PlotCommandOptions {
        std::string dir;
        std::string out;
        std::string gnuplot = "gnuplot";
        int threads = 0;
    };
    auto opt = std::make_shared<PlotCommandOptions>();
    CLI::App* sub = app.add_subcommand("plot", "Figures (PNG 2400 px wide and SVG) of a simulate, modes or sweep output folder");
    sub->add_option("dir", opt->dir, "Output folder of simulate, modes or sweep (--out)")->required();
    sub->add_option("--out,-o", opt->out, "Folder for the figures (default: DIR/plots; files of the same names are replaced)");
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (a name on PATH or a path)")->capture_default_str();
    sub->add_option("--threads,-j", opt->threads, "gnuplot processes drawing at once (0: every CPU this process may use)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();

    return [opt]() {
        const std::string gnuplot = require_gnuplot(opt->gnuplot, "the figures of a run folder");
        const RunPlots plots = run_plots(opt->dir);
        const std::string out = opt->out.empty() ? opt->dir + "/plots" : opt->out;
        OutputFiles files = figure_files(plots.figures, render_figures(gnuplot, plots.figures, opt->threads));
        check_run();
        {
            const CommitSection commit;
            write_output_files(out, files);
        }
        std::printf("Wrote %zu figures of a %s folder (PNG, SVG, their data and gnuplot scripts) to %s/\n", plots.figures.size(),
                    run_kind_name(plots.kind), out.c_str());
        if (!plots.skipped.empty()) {
            std::string list;
            for (const std::string& s : plots.skipped) list += (list.empty() ? "" : ", ") + s;
            std::printf("Not drawn: %s\n", list.c_str());
        }
        return kExitOk;
    };
}

}  // namespace vi::cli
