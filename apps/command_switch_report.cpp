// `vibroimpact switch-report CASE --out DIR`: a contact switch's pull-in and switching transient
// on one page with figures.

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "json_output.hpp"
#include "report/pullin_output.hpp"
#include "report/transient_output.hpp"
#include "figure_output.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "plot/figure_gnuplot.hpp"
#include "stop_signals.hpp"
#include "study/switch/switch_study.hpp"

namespace vi::cli {

CommandBody add_switch_report_command(CLI::App& app) {
    struct SwitchReportCommandOptions {
        std::string case_path;
        std::string out;
        bool json = false;
        std::string gnuplot = "gnuplot";
    };
    auto opt = std::make_shared<SwitchReportCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "switch-report", "A switch's pull-in curve, C-V, f-V and switching transient with its bounce ledger on one page");
    sub->add_option("case", opt->case_path, "Case file (TOML) with [[electrodes]], [initial] and [solver] horizon")->required();
    sub->add_option("--out,-o", opt->out, "Folder for report.html, report.md, the figures and the data files (--out or --json is needed)");
    sub->add_flag("--json", opt->json,
                  "Print the result as JSON on stdout: \"pullin\" (pullin.json) and \"transient\" (summary.json); "
                  "without --out no file is written and no figure drawn");
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (name on PATH or path)")->capture_default_str();

    return [opt]() {
        if (opt->out.empty() && !opt->json) {
            throw InputError("--out: switch-report writes report.html with its figures and data into a folder: give "
                             "--out DIR (or --json for the numbers alone)");
        }
        const Case c = read_case_file(opt->case_path);
        const std::string gnuplot = opt->out.empty() ? std::string() : require_gnuplot(opt->gnuplot, "the figures");
        SwitchStudy study;
        try {
            study = run_switch_study(c);
        } catch (const InputError& e) {
            throw locate_in_case(c, e);
        }
        const auto result_json = [&study] {
            const SimulationRun& t = study.transient;
            return nlohmann::json{{"pullin", pullin_json(study.pullin)},
                                  {"transient", transient_summary_json(study.c, t.built, t.result, t.summary,
                                                                       t.switching ? &*t.switching : nullptr)}};
        };
        if (opt->out.empty()) {
            check_run();
            print_json(result_json());
            return kExitOk;
        }
        const std::vector<FigureSpec> figures = switch_figures(study);
        const std::vector<RenderedFigure> rendered = render_figures(gnuplot, figures, 2);
        std::string command = "vibroimpact switch-report ";
        command += opt->case_path;
        command += " --out ";
        command += opt->out;
        const OutputFiles files = switch_report_files(study, figures, rendered, command);
        // Last chance to stop: from here the files are complete and go into place together.
        check_run();
        {
            const CommitSection commit;
            write_output_files(opt->out, files);
        }
        if (opt->json) {
            print_json(result_json());
            return kExitOk;
        }
        const PullinResult& p = study.pullin;
        std::printf("Wrote %zu files to %s/ (open report.html): V_PI %s, %zu contact episodes, first contact %s\n",
                    files.size(), opt->out.c_str(),
                    p.pullin ? (std::to_string(p.pullin->voltage) + " V").c_str() : "none",
                    study.transient.result.episodes.size(),
                    study.transient.result.episodes.empty()
                        ? "none"
                        : (std::to_string(study.transient.result.episodes.front().t_on * 1e6) + " us").c_str());
        return kExitOk;
    };
}

}  // namespace vi::cli
