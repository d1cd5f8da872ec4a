// `vibroimpact uq CASE --vary 'PATH=normal:MEAN:SD' ...`: the spread of an analysis's results over
// fabrication tolerances, the yield against specs and the Sobol indices of each tolerance, on the
// sweep's engine (threads, MPI ranks, journal, resume, point timeout); docs/uq.md.

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "figure_output.hpp"
#include "study/uq/uq_figures.hpp"
#include "study/uq/uq_report.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "point_runs.hpp"
#include "progress.hpp"
#include "stop_signals.hpp"
#include "study/analyses/sweep_analyses.hpp"
#include "support_model_option.hpp"
#include "sweep/identity.hpp"
#include "uq/sample_design.hpp"
#include "uq/sobol_indices.hpp"
#include "uq/uq_summary.hpp"

namespace vi::cli {
namespace {

struct UqCommandOptions {
    std::string case_path;
    std::vector<std::string> vary, specs, plots;
    std::string gnuplot = "gnuplot";
    std::string analysis = "simulate";
    int modes = 3;
    std::string support_model = "pin";
    std::size_t samples = 256;
    std::string method = "mc";
    std::uint64_t seed = 1;
    bool sensitivity = false;
    std::size_t resamples = 1000;
    std::string out_dir;
    bool resume = false, retry_failed = false, json = false;
    double point_timeout = 60.0;
    int threads = 0;
    ProgressSettings progress;
};

SamplingMethod method_of(const std::string& m) {
    return m == "lhs" ? SamplingMethod::lhs : m == "sobol" ? SamplingMethod::sobol : SamplingMethod::mc;
}

// What the plan keeps besides the run's: the design and the specs, for the summary.
struct UqPlan {
    SampleDesign design;
    UqSettings settings;
    std::vector<std::string> plots;  // columns with figures
};

PointRunPlan make_plan(const UqCommandOptions& o, UqPlan& uq) {
    if (o.resume && o.out_dir.empty()) throw InputError("--resume: needs --out DIR, the folder holding the journal");
    if (o.retry_failed && !o.resume) throw InputError("--retry-failed: goes with --resume (failed samples of a journal)");
    if (o.samples < 2) throw InputError("--samples " + std::to_string(o.samples) + ": a spread needs at least 2 samples");
    if (o.sensitivity && o.samples < kMinSobolBaseSamples) {
        throw InputError("--samples " + std::to_string(o.samples) + ": --sensitivity needs at least " +
                         std::to_string(kMinSobolBaseSamples) +
                         " base samples (its bootstrap intervals need that many rows; it runs N (d + 2) of them)");
    }
    std::string reason;
    const auto text = file_text(o.case_path, reason);
    if (!text) throw InputError(one_line(o.case_path + ": cannot read file (" + reason + ")"));
    PointRunPlan p;
    p.base = read_case_text(*text, o.case_path);
    const std::vector<UqInput> inputs = parse_uq_inputs(o.vary, p.base);
    p.settings.analysis = parse_sweep_analysis(o.analysis);
    p.settings.modes = o.modes;
    p.settings.support_model = parse_support_model(o.support_model);
    p.settings.point_timeout = o.point_timeout;
    p.settings = with_study_analyses(p.settings);
    check_sweep_analysis(p.base, p.settings);
    p.settings.supports = static_cast<int>(p.base.supports.size());
    p.columns = sweep_result_columns(p.settings.analysis, p.settings.modes, p.settings.supports);
    std::vector<std::string> numeric;
    for (const SweepColumn& c : p.columns) {
        if (!sweep_column_is_text(c.name)) numeric.push_back(c.name);
    }
    uq.settings.analysis = o.analysis;
    uq.settings.method = method_of(o.method);
    uq.settings.seed = o.seed;
    uq.settings.resamples = o.resamples;
    for (const std::string& s : o.specs) uq.settings.specs.push_back(parse_yield_spec(s, numeric));
    // Figures of the columns the specs name and of --plot's.
    for (const YieldSpec& s : uq.settings.specs) {
        if (std::find(uq.plots.begin(), uq.plots.end(), s.column) == uq.plots.end()) uq.plots.push_back(s.column);
    }
    for (const std::string& c : o.plots) {
        if (std::find(numeric.begin(), numeric.end(), c) == numeric.end()) {
            std::string names;
            for (const std::string& n : numeric) names += (names.empty() ? "" : ", ") + n;
            throw InputError("--plot " + c + ": no numeric column '" + c + "' in this analysis (one of: " + names + ")");
        }
        if (std::find(uq.plots.begin(), uq.plots.end(), c) == uq.plots.end()) uq.plots.push_back(c);
    }
    uq.design = make_sample_design(inputs, o.samples, uq.settings.method, o.seed, o.sensitivity);
    p.grid = uq.design.grid;
    // The rows depend on the case, the analysis and every run's values (the identity holds them
    // all); specs and the bootstrap only change the summary, so a resume may change them.
    p.fingerprint = fingerprint_of("vibroimpact uq identity 1\n" + sweep_identity_text(*text, p.grid, p.settings));
    p.csv_header = sweep_csv_header(p.grid, p.columns);
    return p;
}

std::string format_value(const nlohmann::json& v) {
    if (!v.is_number()) return "nan";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.5g", v.get<double>());
    return buf;
}

// The text summary: failures, each yield with its interval, the columns' spread, and the Sobol
// indices of the columns the specs name.
void print_summary(const nlohmann::json& j, const UqSettings& s) {
    std::printf("%zu base samples (%s), %zu runs, %zu failed\n", j["samples"].get<std::size_t>(),
                j["method"].get<std::string>().c_str(), j["runs"].get<std::size_t>(), j["failed"].get<std::size_t>());
    std::printf("%-32s %6s %12s %12s %12s %12s %12s\n", "column", "n", "mean", "std", "q5", "q50", "q95");
    for (const auto& [name, c] : j["columns"].items()) {
        if (c["n"].get<std::size_t>() == 0) continue;
        std::printf("%-32s %6zu %12s %12s %12s %12s %12s\n", name.c_str(), c["n"].get<std::size_t>(),
                    format_value(c["mean"]).c_str(), format_value(c["std"]).c_str(),
                    format_value(c["quantiles"]["5"]).c_str(), format_value(c["quantiles"]["50"]).c_str(),
                    format_value(c["quantiles"]["95"]).c_str());
    }
    for (const YieldSpec& spec : s.specs) {
        for (const auto& y : j["columns"][spec.column]["yield"]) {
            if (y["spec"] != spec.text || !y["yield"].is_number()) continue;
            std::printf("yield %s: %s (%zu of %zu; 95 %% Wilson %s .. %s)\n", spec.text.c_str(), format_value(y["yield"]).c_str(),
                        y["passed"].get<std::size_t>(), y["evaluated"].get<std::size_t>(), format_value(y["ci"][0]).c_str(),
                        format_value(y["ci"][1]).c_str());
        }
        const nlohmann::json& sobol = j["columns"][spec.column].value("sobol", nlohmann::json());
        if (!sobol.is_object()) continue;
        for (const auto& [path, x] : sobol.items()) {
            std::printf("  Sobol %s / %s: first %s, total %s\n", spec.column.c_str(), path.c_str(),
                        format_value(x["first"]).c_str(), format_value(x["total"]).c_str());
        }
    }
}

int finish_on_root(const UqCommandOptions& o, const UqPlan& uq, SweepStore& store, const SweepRunInfo& info) {
    if (!store.complete()) return report_interrupted("uq", o.out_dir, store);
    const std::string csv = store.csv();
    const UqTable table = uq_table_from_csv(csv, uq.design.inputs.size());
    nlohmann::json j = uq_summary_json(uq.design, table, uq.settings);
    j["case"] = o.case_path;
    j["case_name"] = info.case_name;
    const std::string json = j.dump(2) + "\n";
    OutputFiles files = {{"uq.json", json}, {"samples.csv", csv}};
    // Figures never cost the results: without gnuplot, or when it fails, the files are written and
    // the exit code says the figures are missing.
    std::string figure_trouble;
    const std::vector<FigureSpec> figures = uq_figures(j, table, uq.design, uq.settings.specs, uq.plots);
    std::map<std::string, std::string> png;
    if (!figures.empty()) {
        try {
            const std::string gnuplot = require_gnuplot(o.gnuplot, "the histograms and Sobol charts");
            for (auto& [name, text] : figure_files(figures, render_figures(gnuplot, figures, 1), &png)) files[name] = std::move(text);
        } catch (const std::runtime_error& e) {
            figure_trouble = e.what();
            png.clear();
        }
    }
    // The page holds the tables in any case; its figures where gnuplot drew them.
    files["uq.html"] = uq_html(j, uq.plots, figures, png);
    {
        const CommitSection commit;
        store.finish_with(o.out_dir, files);
    }
    if (o.json) {
        std::fputs(json.c_str(), stdout);
    } else {
        print_summary(j, uq.settings);
        std::printf("Computed %zu runs in %.3g s on %d threads x %d processes (%zu from the journal); written to %s/ "
                    "(uq.json, samples.csv, uq.html%s)\n",
                    info.computed_this_run, info.wall_s, info.threads, info.processes, info.from_journal,
                    o.out_dir.c_str(), figures.empty() || !figure_trouble.empty() ? "" : ", figures");
    }
    if (!figure_trouble.empty()) {
        std::fprintf(stderr, "vibroimpact: uq: results written without their figures: %s\n", figure_trouble.c_str());
        return kExitFailure;
    }
    const std::size_t failed = j["failed"].get<std::size_t>();
    if (failed > 0) {
        std::fprintf(stderr, "vibroimpact: uq: %zu of %zu runs failed (uq.json's failures and samples.csv's status say "
                             "why; statistics are over the others)\n",
                     failed, store.points());
    }
    return kExitOk;
}

int run_uq(const UqCommandOptions& o) {
    const PointRunOptions run = point_run_options(o, "uq", "runs");
    UqPlan uq;
    return run_points_on_ranks(
        run, [&] { return make_plan(o, uq); },
        [&](const PointRunPlan&, SweepStore& store, const SweepRunInfo& info) { return finish_on_root(o, uq, store, info); });
}

}  // namespace

CommandBody add_uq_command(CLI::App& app) {
    auto opt = std::make_shared<UqCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "uq", "Spread of an analysis over fabrication tolerances: statistics, yield against specs, Sobol indices");
    sub->add_option("case", opt->case_path, "Case file (TOML)")->required();
    sub->add_option("--vary", opt->vary,
                    "PATH=DIST: a case value and its distribution: normal:MEAN:SD, uniform:LOW:HIGH, "
                    "lognormal:MEDIAN:SIGMA_LOG, truncnormal:MEAN:SD:LOW:HIGH (SI units, or units as in --set of "
                    "sweep; SIGMA_LOG a plain number). Repeat for more")
        ->required()
        ->allow_extra_args(false)
        ->type_name("PATH=DIST");
    sub->add_option("--analysis", opt->analysis, "What each sample computes, as sweep --analysis")
        ->check(CLI::IsMember({"simulate", "modes", "pullin", "stiction", "air-q"}))
        ->capture_default_str();
    sub->add_option("--modes", opt->modes, "Bending modes per sample of a modes analysis")->check(CLI::Range(1, 100));
    add_support_model_option(*sub, opt->support_model);
    sub->add_option("--samples,-n", opt->samples,
                    "Base samples N (with --sensitivity N (d + 2) runs for d inputs; at least 32 there)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{10'000'000}))
        ->capture_default_str();
    sub->add_option("--method", opt->method,
                    "mc (independent draws), lhs (Latin hypercube) or sobol (Sobol sequence with a random digital shift)")
        ->check(CLI::IsMember({"mc", "lhs", "sobol"}))
        ->capture_default_str();
    sub->add_option("--seed", opt->seed, "Seed of the sampling and the bootstrap: the same seed, the same samples")
        ->capture_default_str();
    sub->add_option("--spec", opt->specs, "COLUMN<=VALUE or COLUMN>=VALUE (SI): a yield is reported for each; repeat")
        ->allow_extra_args(false);
    sub->add_flag("--sensitivity", opt->sensitivity,
                  "First-order and total Sobol indices of every input (Saltelli's scheme: N (d + 2) runs)");
    sub->add_option("--bootstrap", opt->resamples, "Bootstrap resamples of the intervals of std and Sobol indices")
        ->check(CLI::Range(std::size_t{100}, std::size_t{100000}))
        ->capture_default_str();
    sub->add_option("--out,-o", opt->out_dir, "Folder for uq.json, samples.csv, uq.html and the journal (required)")->required();
    sub->add_flag("--resume", opt->resume, "Finish the study interrupted in --out DIR without redoing its runs");
    sub->add_flag("--retry-failed", opt->retry_failed, "With --resume: compute again the runs the journal holds as failed");
    sub->add_option("--point-timeout", opt->point_timeout, "Wall-clock limit of one run [s] (0: none)")
        ->check(CLI::Range(0.0, 1e9))
        ->capture_default_str();
    sub->add_option("--threads,-j", opt->threads, "Worker threads per process (0: every CPU this process may use)")
        ->check(CLI::Range(0, 4096))
        ->capture_default_str();
    sub->add_flag("--json", opt->json, "Print uq.json on stdout instead of the text summary");
    sub->add_option("--plot", opt->plots,
                    "A column to draw (histogram, and Sobol chart with --sensitivity) besides those the specs name; "
                    "repeat for more")
        ->allow_extra_args(false);
    sub->add_option("--gnuplot", opt->gnuplot, "gnuplot executable (name on PATH or path)")->capture_default_str();
    add_progress_options(*sub, opt->progress);
    sub->footer("See docs/uq.md for the estimators, their intervals and how many samples a confidence needs.");
    return [opt]() { return run_uq(*opt); };
}

}  // namespace vi::cli
