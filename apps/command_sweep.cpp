// `vibroimpact sweep CASE --set PATH=SPEC ...`: one analysis per point of a parameter grid, on every
// core and, under mpirun, on every rank; a journal lets an interrupted sweep resume.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "json_output.hpp"
#include "io/case_reader.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "point_runs.hpp"
#include "progress.hpp"
#include "stop_signals.hpp"
#include "study/analyses/sweep_analyses.hpp"
#include "support_model_option.hpp"
#include "sweep/case_paths.hpp"
#include "sweep/column_docs.hpp"
#include "sweep/identity.hpp"

namespace vi::cli {
namespace {

struct SweepCommandOptions {
    std::string case_path;
    std::vector<std::string> sets;
    std::string analysis = "simulate";
    std::string list_columns;
    std::string out_dir;
    int threads = 0;
    int modes = 3;
    std::string support_model = "pin";
    bool resume = false;
    bool json = false;
    bool retry_failed = false;
    double point_timeout = 60.0;
    ProgressSettings progress;
};

PointRunPlan make_plan(const SweepCommandOptions& o) {
    if (o.case_path.empty()) throw InputError("sweep: give the CASE file (or --list-columns ANALYSIS)");
    if (o.resume && o.out_dir.empty()) throw InputError("--resume: needs --out DIR, the folder holding the journal");
    if (o.retry_failed && !o.resume) throw InputError("--retry-failed: goes with --resume (failed points of a journal)");
    std::string reason;
    const auto text = file_text(o.case_path, reason);
    if (!text) throw InputError(one_line(o.case_path + ": cannot read file (" + reason + ")"));
    PointRunPlan p;
    p.base = read_case_text(*text, o.case_path);
    p.grid = parse_sweep_grid(o.sets, p.base);
    p.settings.analysis = parse_sweep_analysis(o.analysis);
    p.settings.modes = o.modes;
    p.settings.support_model = parse_support_model(o.support_model);
    p.settings.point_timeout = o.point_timeout;
    p.settings = with_study_analyses(p.settings);
    check_sweep_analysis(p.base, p.settings);
    p.settings.supports = static_cast<int>(p.base.supports.size());
    p.columns = sweep_result_columns(p.settings.analysis, p.settings.modes, p.settings.supports);
    p.fingerprint = fingerprint_of(sweep_identity_text(*text, p.grid, p.settings));
    p.csv_header = sweep_csv_header(p.grid, p.columns);
    return p;
}

// The root's last step: the files of a complete sweep, or how to resume an interrupted one.
int finish_on_root(const SweepCommandOptions& o, const PointRunPlan& plan, SweepStore& store, SweepRunInfo info) {
    if (!store.complete()) return report_interrupted("sweep", o.out_dir, store);
    const auto failures = store.failures();
    info.case_path = o.case_path;
    info.failed = failures.size();
    info.failures = failures;
    const nlohmann::json summary = sweep_summary_json(plan.grid, info);
    if (o.json) {
        // Read before finish(): the store's rows are what the CSV holds.
        nlohmann::json j = summary;
        j["table"] = csv_as_json(store.csv(), SweepStore::kCsvName);
        if (!o.out_dir.empty()) {
            const CommitSection commit;
            store.finish(o.out_dir, summary.dump(2) + "\n");
        }
        print_json(j);
    } else if (o.out_dir.empty()) {
        std::fputs(store.csv().c_str(), stdout);
    } else {
        const CommitSection commit;
        store.finish(o.out_dir, summary.dump(2) + "\n");
        std::printf("Written %zu points to %s/%s and %s\n", store.points(), o.out_dir.c_str(), SweepStore::kCsvName,
                    SweepStore::kJsonName);
    }
    if (!failures.empty()) {
        std::fprintf(stderr, "vibroimpact: sweep: %zu of %zu points failed (the status column says why)\n",
                     failures.size(), store.points());
    }
    return kExitOk;
}

int run_sweep(const SweepCommandOptions& o) {
    const PointRunOptions run = point_run_options(o, "sweep", "points");
    return run_points_on_ranks(
        run, [&] { return make_plan(o); },
        [&](const PointRunPlan& plan, SweepStore& store, const SweepRunInfo& info) {
            return finish_on_root(o, plan, store, info);
        });
}

std::string paths_help() {
    std::string s = "PATH is one of (i: support or load number from 0, k: 0 or 1):\n ";
    std::size_t width = 1;
    for (const std::string& p : case_path_forms()) {
        if (width + p.size() + 1 > 100) {
            s += "\n ";
            width = 1;
        }
        s += " " + p;
        width += p.size() + 1;
    }
    return s + "\nSee docs/sweeps.md for the columns, resuming, MPI and exit codes.";
}

}  // namespace

CommandBody add_sweep_command(CLI::App& app) {
    auto opt = std::make_shared<SweepCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "sweep", "Run an analysis over a grid of case values, on every core (and every MPI rank under mpirun)");
    sub->add_option("case", opt->case_path, "Case file (TOML)");
    sub->add_option("--set", opt->sets,
                    "PATH=SPEC: a value of the case and the values it takes, in SI units (m, Pa, N/m, N s/m, s; "
                    "positions as x/l; gap and prestress in m). SPEC: a list 0.5,0.67,0.78, a range "
                    "start:stop:count or log:start:stop:count. Several --set make a full grid (the last varies "
                    "fastest)")
        ->allow_extra_args(false)
        ->type_name("PATH=SPEC");
    sub->add_option("--analysis", opt->analysis,
                    "What each point computes: simulate (transient), modes, pullin, stiction or air-q (docs/sweeps.md, "
                    "Analyses; --list-columns ANALYSIS prints its columns)")
        ->check(CLI::IsMember({"simulate", "modes", "pullin", "stiction", "air-q"}))
        ->capture_default_str();
    sub->add_option("--list-columns", opt->list_columns,
                    "Print the result columns of an analysis with their units and meanings, and exit")
        ->check(CLI::IsMember({"simulate", "modes", "pullin", "stiction", "air-q"}))
        ->type_name("ANALYSIS");
    CLI::Option* modes = sub->add_option("--modes", opt->modes, "Bending modes per point of a modes sweep")
                             ->check(CLI::Range(1, 100))
                             ->capture_default_str();
    CLI::Option* support_model = add_support_model_option(*sub, opt->support_model);
    sub->add_option("--out,-o", opt->out_dir,
                    "Folder for sweep.csv and sweep.json, and for the journal of finished points (otherwise the CSV "
                    "goes to stdout and an interrupted sweep is lost)");
    sub->add_flag("--json", opt->json,
                  "Print the result as JSON on stdout (sweep.json's fields and \"table\": the columns and rows of "
                  "sweep.csv) instead of the CSV or the line naming the files");
    sub->add_flag("--resume", opt->resume, "Finish the sweep interrupted in --out DIR without redoing its points");
    sub->add_flag("--retry-failed", opt->retry_failed,
                  "With --resume: compute again the points the journal holds as failed (error or timeout)");
    sub->add_option("--point-timeout", opt->point_timeout,
                    "Wall-clock limit of one point [s]; a point that reaches it gets 'timeout: ...' in its status "
                    "and the sweep goes on (0: no limit)")
        ->check(CLI::Range(0.0, 1e9))
        ->capture_default_str();
    sub->add_option("--threads,-j", opt->threads,
                    "Worker threads per process (0: every CPU this process may use, its affinity and cgroup CPU "
                    "quota; under MPI, shared among the ranks that may use the same CPUs)")
        ->check(CLI::Range(0, 4096))
        ->capture_default_str();
    add_progress_options(*sub, opt->progress);
    sub->footer(paths_help());
    return [opt, modes, support_model]() {
        if (!opt->list_columns.empty()) {
            std::fputs(sweep_column_text(parse_sweep_analysis(opt->list_columns)).c_str(), stdout);
            return kExitOk;
        }
        // Options only a modes sweep uses are refused rather than ignored.
        if (opt->analysis != "modes") {
            for (const CLI::Option* o : {modes, support_model}) {
                if (o->count() > 0) {
                    throw InputError(o->get_name() + ": applies to --analysis modes, not to a " + opt->analysis + " sweep");
                }
            }
        }
        return run_sweep(*opt);
    };
}

}  // namespace vi::cli
