// `vibroimpact paper`: the paper's whole numerical study (Figs. 2-11) with its report, from the
// built-in examples/paper/ cases, into one output folder.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "study/paper/claims.hpp"
#include "study/paper/study.hpp"
#include "commands.hpp"
#include "json_output.hpp"
#include "progress.hpp"
#include "model/input_error.hpp"
#include "io/output_files.hpp"
#include "io/units.hpp"
#include "model/run_control.hpp"
#include "plot/figure_gnuplot.hpp"
#include "study/paper/figures.hpp"
#include "study/paper/report.hpp"
#include "stop_signals.hpp"

namespace vi::cli {
namespace {

// Fails early, before the study's seconds of work, when the folder cannot be made or written: makes
// it (and removes again what it made) or writes and removes a probe file in it.
void check_output_folder(const std::string& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path p = fs::absolute(dir, ec);
    if (ec) throw std::runtime_error(dir + ": cannot create folder: " + ec.message());
    if (fs::exists(p, ec)) {
        if (!fs::is_directory(p, ec)) throw std::runtime_error(dir + ": exists and is not a folder");
        const fs::path probe = p / ".vibroimpact-write-probe";
        const bool ok = static_cast<bool>(std::ofstream(probe));
        fs::remove(probe, ec);
        if (!ok) throw std::runtime_error(dir + ": cannot write in this folder");
        return;
    }
    fs::path first_new = p;
    while (first_new.has_parent_path() && first_new.parent_path() != first_new && !fs::exists(first_new.parent_path(), ec)) {
        first_new = first_new.parent_path();
    }
    fs::create_directories(p, ec);
    if (ec) throw std::runtime_error(dir + ": cannot create folder: " + ec.message());
    fs::remove_all(first_new, ec);
}

}  // namespace

CommandBody add_paper_command(CLI::App& app) {
    struct PaperCommandOptions {
        std::string out;
        bool json = false;
        int threads = 0;
        int positions = 50;
        int modal_positions = 100;
        int prestress_points = 26;
        std::string scan_horizon = "500 us";
        std::string examples;
        std::string gnuplot = "gnuplot";
        bool quiet = false;
        ProgressSettings progress;
    };
    auto opt = std::make_shared<PaperCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "paper", "The paper's numerical study (Figs. 2-11: PNG, SVG, CSV) and report.html comparing its claims with ours");
    sub->add_option("--out,-o", opt->out, "Output folder (created; files of the same names are replaced); --out or --json is needed");
    sub->add_flag("--json", opt->json,
                  "Print the claims as JSON on stdout (claims.json, with the count that agree); without --out no file is "
                  "written and no figure drawn");
    sub->add_option("--threads,-j", opt->threads, "Worker threads (0: every CPU this process may use: its affinity and cgroup CPU quota)")->check(CLI::Range(0, 1024))->capture_default_str();
    sub->add_option("--positions", opt->positions,
                    "Support positions of the transient scans, evenly over x0/l in [0.3, 1] (0.67, 0.78, 0.87 always added)")
        ->check(CLI::Range(2, 100000))
        ->capture_default_str();
    sub->add_option("--modal-positions", opt->modal_positions, "Support positions of the modal scans (Figs. 6-8), x0/l = 1/N ... 1")
        ->check(CLI::Range(2, 100000))
        ->capture_default_str();
    sub->add_option("--prestress-points", opt->prestress_points, "Prestress values of Fig. 9, evenly over Delta/l in [0, 0.05]")
        ->check(CLI::Range(2, 100000))
        ->capture_default_str();
    sub->add_option("--scan-horizon", opt->scan_horizon,
                    "Horizon of the support-position transients (Figs. 4, 5, 10), a time with its unit, e.g. \"300 us\"")
        ->capture_default_str();
    sub->add_option("--examples", opt->examples,
                    "Read cantilever.toml, free_impact_tip.toml and free_impact_prestress.toml from this folder instead of "
                    "the built-in copies of examples/paper/");
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (a name on PATH or a path)")->capture_default_str();
    CLI::Option* quiet = sub->add_flag("--quiet,-q", opt->quiet, "No progress on stderr (--progress none)");
    quiet->excludes(add_progress_options(*sub, opt->progress));

    return [opt]() {
        using Clock = std::chrono::steady_clock;
        const auto t0 = Clock::now();
        auto elapsed = [t0]() { return seconds_since(t0); };
        // The study's jobs counted, and a line as each part of it (and each later stage) ends.
        Progress jobs("paper", "jobs", 0, 0, opt->quiet ? ProgressStyle::none : progress_style(opt->progress),
                      opt->progress.interval_s);
        auto progress = [&jobs, elapsed](const std::string& line) {
            char at[32];
            std::snprintf(at, sizeof at, "[%5.1f s] ", elapsed());
            jobs.say("paper: " + std::string(at) + line);
        };
        double scan_horizon = 0.0;
        try {
            scan_horizon = parse_quantity(opt->scan_horizon, Dimension::time);
        } catch (const std::invalid_argument& e) {
            throw InputError("--scan-horizon: " + std::string(e.what()));
        }
        if (!(scan_horizon > 0.0)) throw InputError("--scan-horizon: must be positive");
        if (opt->out.empty() && !opt->json) {
            throw InputError("--out: paper writes report.html with its figures and data into a folder: give --out DIR "
                             "(or --json for the claims alone)");
        }
        if (!opt->out.empty()) check_output_folder(opt->out);
        const auto gnuplot = opt->out.empty() ? std::optional<std::string>("") : find_gnuplot(opt->gnuplot);
        if (!gnuplot) {
            throw std::runtime_error("gnuplot: '" + opt->gnuplot +
                                     "' not found; the figures need it (Debian: apt-get install gnuplot-nox, or bash scripts/install-deps)");
        }

        PaperStudyOptions so;
        so.cases = load_paper_cases(opt->examples);
        so.positions = opt->positions;
        so.modal_positions = opt->modal_positions;
        so.prestress_points = opt->prestress_points;
        so.position_horizon = scan_horizon;
        so.threads = opt->threads;
        so.progress = progress;
        so.jobs_done = [&jobs](std::size_t done, std::size_t total) {
            if (done == 0) {
                jobs.set_total(total);
            } else {
                jobs.advance();
            }
        };
        const PaperStudy study = [&] {
            const ProgressTicker ticker(jobs);
            return run_paper_study(so);
        }();
        jobs.finish();
        progress("study done: " + std::to_string(study.timing.transients) + " transients on " + std::to_string(study.timing.threads) +
                 " threads");

        const std::vector<Claim> claims = paper_claims(study);
        int agree = 0;
        for (const Claim& c : claims) agree += c.verdict == Verdict::agrees;
        if (opt->out.empty()) {
            check_run();
            print_json({{"agree", agree}, {"claims_total", claims.size()}, {"claims", nlohmann::json::parse(claims_json(claims))}});
            return kExitOk;
        }
        const std::vector<FigureSpec> figures = paper_figures(study);
        const auto f0 = Clock::now();
        const std::vector<RenderedFigure> rendered = render_figures(*gnuplot, figures, study.timing.threads);
        ReportRun run;
        run.version = kVersionText;
        run.command = "vibroimpact paper --out " + opt->out;
        if (opt->positions != 50) run.command += " --positions " + std::to_string(opt->positions);
        if (opt->modal_positions != 100) run.command += " --modal-positions " + std::to_string(opt->modal_positions);
        if (opt->prestress_points != 26) run.command += " --prestress-points " + std::to_string(opt->prestress_points);
        if (opt->scan_horizon != "500 us") run.command += " --scan-horizon '" + opt->scan_horizon + "'";
        if (!opt->examples.empty()) run.command += " --examples " + opt->examples;
        run.figures_s = seconds_since(f0);
        progress("figures drawn (" + std::to_string(figures.size()) + " with gnuplot)");
        run.total_s = elapsed();
        const OutputFiles files = paper_output_files(study, claims, figures, rendered, run);
        // Last chance to stop: from here the files are complete and go into place together.
        check_run();
        {
            const CommitSection commit;
            write_output_files(opt->out, files);
        }
        if (opt->json) {
            print_json({{"agree", agree}, {"claims_total", claims.size()}, {"claims", nlohmann::json::parse(files.at("claims.json"))}});
            return kExitOk;
        }
        std::printf("Wrote %zu files to %s/ (open report.html): %d of %zu claims of the paper agree; %.1f s\n", files.size(),
                    opt->out.c_str(), agree, claims.size(), elapsed());
        return kExitOk;
    };
}

}  // namespace vi::cli
