// `vibroimpact optimize CASE --vary PATH=LOW:HIGH ... --minimize QUANTITY [--constraint ...]`:
// the best design in a box of case values (docs/optimization.md).

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "figure_output.hpp"
#include "progress.hpp"
#include "design/design_journal.hpp"
#include "design/optimize_output.hpp"
#include "design/optimizer.hpp"
#include "io/case_reader.hpp"
#include "io/csv_writer.hpp"
#include "io/number_text.hpp"
#include "io/text_file.hpp"
#include "io/output_files.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "plot/figure_gnuplot.hpp"
#include "stop_signals.hpp"
#include "study/analyses/design_setup.hpp"

namespace vi::cli {
namespace {

CsvCell count(std::size_t n) { return csv_count(static_cast<std::int64_t>(n)); }

FigureSpec convergence_figure(const DesignProblem& p, const OptimizeResult& r) {
    const std::string q = p.columns[p.objective].name;
    CsvTable t;
    t.header = {"index", q, "best_" + q};  // the objective where the design is feasible, and the best so far
    for (const DesignEvaluation& e : r.evaluations) {
        t.add_row({count(e.index), e.feasible ? csv_number(e.outcome.objective) : csv_missing(), csv_number(e.best)});
    }
    const std::string data = t.str();
    FigureSpec f;
    f.name = "convergence";
    f.title = "Convergence: " + q + " against evaluations";
    f.caption = "Each feasible design's " + q + " (points) and the best so far (line), global stage then local.";
    f.data = {{"convergence.csv", data}};
    f.plot = "set datafile separator ','\nset key top right\nset xlabel 'evaluation'\nset ylabel " + gp_quote(q) +
             " noenhanced\n";
    if (!r.best) {
        // Nothing to draw (gnuplot refuses a plot without one defined point): an empty frame that says so.
        f.caption = "No design was feasible: evaluations.csv says why each failed.";
        f.plot += "set xrange [0:" + std::to_string(std::max<std::size_t>(r.evaluations.size(), 1)) +
                  "]\nset yrange [0:1]\nunset ytics\nset label 1 'no feasible design' at graph 0.5, 0.5 center\n"
                  "plot NaN notitle\n";
        return f;
    }
    f.plot += "plot 'convergence.csv' using 1:2 every ::1 with points pt 7 ps 0.6 title 'design', "
              "'' using 1:3 every ::1 with steps lw 2 title 'best so far'\n";
    return f;
}

struct OptimizeCommandOptions {
    std::string case_path;
    std::vector<std::string> vary, constraints;
    std::string minimize, maximize;
    std::string analysis = "simulate";
    int modes = 3;
    int max_evals = 100, global_evals = 0, threads = 0;
    double point_timeout = 60.0;
    std::string out = "out/optimize";
    std::string gnuplot = "gnuplot";
    bool json = false;
    bool resume = false;
    ProgressSettings progress;
};

std::string command_text(const OptimizeCommandOptions& o, const DesignProblem& p) {
    std::string command = "vibroimpact optimize " + o.case_path;
    for (const std::string& v : o.vary) command += " --vary '" + v + "'";
    if (o.analysis != "simulate") command += " --analysis " + o.analysis;
    if (o.analysis == "modes") command += " --modes " + std::to_string(o.modes);
    command += p.maximize ? " --maximize " + o.maximize : " --minimize " + o.minimize;
    for (const std::string& c : o.constraints) command += " --constraint '" + c + "'";
    command += " --max-evals " + std::to_string(o.max_evals);
    if (o.global_evals > 0) command += " --global-evals " + std::to_string(o.global_evals);
    return command;
}

void print_result(const OptimizeCommandOptions& o, const DesignProblem& p, const OptimizeResult& r, double wall_s) {
    std::printf("%s %s: %zu designs (global stage: %s; local stage: %s)\n", p.maximize ? "Maximise" : "Minimise",
                p.columns[p.objective].name.c_str(), r.evaluations.size(), r.global_end.c_str(), r.local_end.c_str());
    std::printf("Computed %zu designs in %zu rounds on %d threads (%zu computed ahead and not used), %.3g s",
                r.computed, r.batches, r.threads, r.unused_guesses, wall_s);
    if (r.reused > 0) std::printf("; %zu designs from the journal of a stopped run", r.reused);
    std::printf("\n");
    if (r.best) {
        const DesignEvaluation& b = r.evaluations[*r.best];
        std::printf("Best design (evaluation %zu): %s = %s\n", b.index, p.columns[p.objective].name.c_str(),
                    round_trip_text(*b.outcome.objective).c_str());
        for (std::size_t i = 0; i < b.x.size(); ++i) {
            std::printf("  %s = %s\n", p.variables[i].path.text().c_str(), round_trip_text(b.x[i]).c_str());
        }
        for (std::size_t k = 0; k < p.constraints.size(); ++k) {
            std::printf("  constraint %s: %s\n", p.constraints[k].text.c_str(),
                        round_trip_text(*b.outcome.constraints[k]).c_str());
        }
    }
    std::printf("Written to %s/\n", o.out.c_str());
}

DesignProblem read_problem(const OptimizeCommandOptions& o, const std::string& case_text) {
    return design_problem(read_case_text(case_text, o.case_path),
                          {o.vary, o.minimize, o.maximize, o.constraints, o.analysis, o.modes, o.point_timeout});
}

// The search, reported as it goes: designs used of --max-evals (the search may end sooner), those
// of the journal not in the rate, and the best objective so far.
OptimizeResult search(const DesignProblem& p, const OptimizeOptions& o, ProgressStyle style, double interval_s) {
    std::set<std::vector<std::uint64_t>> journal;
    for (const ComputedDesign& d : o.known) journal.insert(design_key(d.x));
    Progress progress("optimize", "designs", static_cast<std::size_t>(o.max_evaluations), 0, style, interval_s, true);
    const ProgressTicker ticker(progress);
    const std::string& q = p.columns[p.objective].name;
    return optimize_design(p, o, [&](const DesignEvaluation& e) {
        if (journal.count(design_key(e.x)) > 0) {
            progress.skip();
        } else {
            progress.advance();
        }
        if (e.best) {
            char best[64];
            std::snprintf(best, sizeof best, "%.6g", *e.best);
            progress.set_note("best " + q + " " + best);
        }
    });
}

// The search with its journal, then the files all together; a stop keeps the journal and says how
// to go on.
int run_optimize(const OptimizeCommandOptions& opt) {
    if (opt.minimize.empty() == opt.maximize.empty()) throw InputError("optimize: give one of --minimize or --maximize");
    if (opt.global_evals >= opt.max_evals) {
        throw InputError("--global-evals " + std::to_string(opt.global_evals) + ": must be below --max-evals " +
                         std::to_string(opt.max_evals) +
                         " (it is the global stage's share of them; the local stage needs one at least)");
    }
    const std::string gnuplot = require_gnuplot(opt.gnuplot, "the convergence figure");
    const ProgressStyle style = progress_style(opt.progress);
    std::string reason;
    const auto case_text = file_text(opt.case_path, reason);
    if (!case_text) throw InputError(one_line(opt.case_path + ": cannot read file (" + reason + ")"));
    const DesignProblem p = read_problem(opt, *case_text);
    OptimizeOptions o;
    o.max_evaluations = opt.max_evals;
    o.global_evaluations = opt.global_evals;
    o.threads = opt.threads;
    DesignJournal journal(opt.out, opt.resume, design_identity_text(*case_text, p), p);
    o.known = journal.designs();
    o.computed = [&journal](const ComputedDesign& d) { journal.append(d); };

    OptimizeResult r;
    nlohmann::json j;
    std::optional<std::string> figure_failed;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        r = search(p, o, style, opt.progress.interval_s);
        const double wall_s = seconds_since(t0);
        j = optimize_result_json(p, r, command_text(opt, p));
        j["run"] = optimize_run_json(r, wall_s);
        OutputFiles files;
        files["optimize.json"] = j.dump(2) + "\n";
        files["evaluations.csv"] = evaluations_csv(p, r);
        figure_failed = write_with_figures(opt.out, std::move(files), {convergence_figure(p, r)}, gnuplot);
        journal.remove();
        if (opt.json) {
            std::printf("%s\n", j.dump(2).c_str());
        } else {
            print_result(opt, p, r, wall_s);
        }
    } catch (const InputError&) {
        // A refusal leaves nothing behind: a journal this run started goes with it.
        if (journal.started_here()) journal.remove();
        throw;
    } catch (const StopRequested& s) {
        std::fprintf(stderr,
                     "vibroimpact: optimize interrupted: %zu designs computed, kept in %s; run the same command with "
                     "--resume to go on\n",
                     journal.size(), journal.path().c_str());
        return kExitStoppedBase + (s.signal() > 0 ? s.signal() : SIGINT);
    }
    if (figure_failed) {
        std::fprintf(stderr, "vibroimpact: optimize: the convergence figure was not drawn (%s); optimize.json and "
                             "evaluations.csv are written in %s\n", figure_failed->c_str(), opt.out.c_str());
        return kExitFailure;
    }
    if (!r.best) {
        std::fprintf(stderr, "vibroimpact: optimize: no design met the constraints and ran to the end in %zu evaluations "
                             "(evaluations.csv says why each failed)\n", r.evaluations.size());
        return kExitFailure;
    }
    return kExitOk;
}

}  // namespace

CommandBody add_optimize_command(CLI::App& app) {
    auto opt = std::make_shared<OptimizeCommandOptions>();
    CLI::App* sub = app.add_subcommand("optimize", "The design that minimises (or maximises) a reported quantity in a box of case values");
    sub->add_option("case", opt->case_path, "Case file (TOML)")->required();
    sub->add_option("--vary", opt->vary, "PATH=LOW:HIGH, SI units, as --set of sweep (repeat for more)")->required();
    sub->add_option("--analysis", opt->analysis,
                    "What each design computes, as sweep --analysis: simulate, modes, pullin, stiction or air-q (sweep "
                    "--list-columns ANALYSIS lists its quantities)")
        ->check(CLI::IsMember({"simulate", "modes", "pullin", "stiction", "air-q"}))
        ->capture_default_str();
    sub->add_option("--modes", opt->modes, "Bending modes of each design of a modes analysis")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    auto* mn = sub->add_option("--minimize", opt->minimize, "Reported quantity to minimise (a sweep column, e.g. z_max, Tp_s)");
    auto* mx = sub->add_option("--maximize", opt->maximize, "Reported quantity to maximise");
    mn->excludes(mx);
    sub->add_option("--constraint", opt->constraints, "NAME<=VALUE or NAME>=VALUE on a reported quantity (repeat for more)");
    sub->add_option("--max-evals", opt->max_evals, "Designs computed at most, both stages together")
        ->check(CLI::Range(2, 100000))->capture_default_str();
    sub->add_option("--global-evals", opt->global_evals, "Of those, the global stage's (0: half)")
        ->check(CLI::Range(0, 100000))->capture_default_str();
    sub->add_option("--point-timeout", opt->point_timeout, "Wall-clock limit of one design [s] (0: none)")
        ->check(CLI::Range(0.0, 1e9))->capture_default_str();
    sub->add_option("--threads,-j", opt->threads,
                    "Worker threads (0: every CPU this process may use, as sweep); the result does not depend on it")
        ->check(CLI::Range(0, 4096))->capture_default_str();
    sub->add_option("--out,-o", opt->out, "Folder for optimize.json, evaluations.csv and the convergence figure")
        ->capture_default_str();
    sub->add_flag("--resume", opt->resume,
                  "Go on with the optimisation stopped in --out (its journal): the designs computed are not computed "
                  "again, and the result is the one of an uninterrupted run");
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (name on PATH or path)")->capture_default_str();
    sub->add_flag("--json", opt->json, "Print optimize.json on stdout instead of text");
    add_progress_options(*sub, opt->progress);

    return [opt]() { return run_optimize(*opt); };
}

}  // namespace vi::cli
