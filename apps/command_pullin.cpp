// `vibroimpact pullin CASE`: the static response to the electrodes' voltage, through pull-in.

#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "progress.hpp"
#include "statics/pullin.hpp"
#include "impacts/dynamic_pullin.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "io/units.hpp"
#include "model/input_error.hpp"
#include "report/pullin_output.hpp"

namespace vi::cli {
namespace {

// The dynamic pull-in's transients run over a horizon the command sets (--horizon, or ten periods
// of mode 1), not the case file's: a check that refuses it names the option, or says where the
// default came from, rather than the case file's solver.horizon line.
InputError blame_horizon(const Case& c, const InputError& e, const std::string& horizon_option) {
    const std::string what = e.what();
    const std::string horizon = "solver.horizon: ", step = "solver.output_step: ";
    const std::string option =
        horizon_option.empty() ? "--horizon (default: ten periods of mode 1)" : "--horizon " + horizon_option;
    if (what.rfind(horizon, 0) == 0) return InputError(option + ": " + what.substr(horizon.size()));
    // The case's output step against the command's horizon: both named, the option first.
    if (what.rfind(step, 0) == 0 && what.find("horizon") != std::string::npos) {
        return InputError(option + ": the case's " + locate_in_case(c, e).what());
    }
    return locate_in_case(c, e);
}

}  // namespace

CommandBody add_pullin_command(CLI::App& app) {
    struct PullinCommandOptions {
        std::string case_path;
        bool json = false;
        std::string out_dir;
        PullinOptions pullin;
        bool dynamic = false;
        std::string horizon;
        DynamicPullinOptions dyn;
        ProgressSettings progress;
    };
    auto opt = std::make_shared<PullinCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "pullin", "Static pull-in: equilibria against voltage, pull-in, touch-down, release, C-V and f-V");
    sub->add_option("case", opt->case_path, "Case file (TOML) with at least one [[electrodes]]")->required();
    sub->add_option("--steps", opt->pullin.steps, "Continuation steps over the air gap of electrodes[0]")
        ->check(CLI::Range(10, 100000));
    sub->add_flag("--dynamic", opt->dynamic,
                  "Also the dynamic (step) pull-in voltage, by bisection on transients (docs/electrostatics.md)");
    const std::vector<CLI::Option*> dynamic_only{
        sub->add_option("--horizon", opt->horizon, "--dynamic: length of each transient (default 10 periods of mode 1)"),
        sub->add_option("--bisections", opt->dyn.bisection.bisections, "--dynamic: most transients after the bracket")
            ->check(CLI::Range(1, 200)),
        sub->add_option("--rel-width", opt->dyn.bisection.rel_width, "--dynamic: relative width of the final bracket")
            ->check(CLI::Range(1e-12, 0.5))};
    sub->add_flag("--json", opt->json, "Print one JSON document on stdout instead of text");
    sub->add_option("--out,-o", opt->out_dir, "Folder for pullin.json, pullin_branch.csv, pullin_frequencies.csv");
    add_progress_options(*sub, opt->progress);

    return [opt, dynamic_only]() {
        // Bad options are refused before any work, and so are options that would do nothing.
        for (const CLI::Option* o : dynamic_only) {
            if (o->count() > 0 && !opt->dynamic) {
                throw InputError(o->get_name() + ": applies to --dynamic (the step pull-in), which is not asked for");
            }
        }
        double horizon = 0.0;
        if (!opt->horizon.empty()) {
            try {
                horizon = parse_quantity(opt->horizon, Dimension::time);
            } catch (const std::invalid_argument& e) {
                throw InputError("--horizon: " + std::string(e.what()));
            }
            if (!(horizon > 0.0)) throw InputError("--horizon: must be positive (e.g. \"100 us\")");
        }
        const ProgressStyle style = progress_style(opt->progress);
        const Case c = read_case_file(opt->case_path);
        PullinResult r;
        try {
            // The branch in step lengths of the air gap, then the frequency points.
            PullinOptions po = opt->pullin;
            Progress progress("pullin", "steps", static_cast<std::size_t>(po.steps + po.frequency_points), 0, style,
                              opt->progress.interval_s);
            po.progress = [&progress](int units, int unused) {
                progress.advance(static_cast<std::size_t>(units));
                progress.skip(static_cast<std::size_t>(unused));
            };
            const ProgressTicker ticker(progress);
            r = trace_pullin(c, po);
        } catch (const InputError& e) {
            throw locate_in_case(c, e);
        }
        std::optional<DynamicPullinResult> dyn;
        if (opt->dynamic) {
            if (!r.pullin) {
                std::fprintf(stderr, "vibroimpact pullin: --dynamic needs a static pull-in to bracket, and the branch has "
                                     "none (%s)\n", r.touchdown ? "a support closes first" : r.end.c_str());
                return kExitFailure;
            }
            DynamicPullinOptions o = opt->dyn;
            o.horizon = horizon;
            // Transients of the bisection, at most (it ends once the bracket is narrow enough).
            Progress progress("pullin --dynamic", "transients",
                              static_cast<std::size_t>(most_step_trials(o.lower_fraction, 1.0, o.bisection)), 0, style,
                              opt->progress.interval_s, true);
            o.bisection.trial_done = [&progress](const StepTrial&) { progress.advance(); };
            const ProgressTicker ticker(progress);
            try {
                dyn = dynamic_pullin(c, r.pullin->voltage, o);
            } catch (const InputError& e) {
                throw blame_horizon(c, e, opt->horizon);
            }
        }
        nlohmann::json j = pullin_json(r);
        if (dyn) j["dynamic"] = dynamic_pullin_json(*dyn);
        if (!opt->out_dir.empty()) {
            OutputFiles files = pullin_files(r);
            files["pullin.json"] = j.dump(2) + "\n";
            write_output_files(opt->out_dir, files);
        }
        if (opt->json) {
            std::printf("%s\n", j.dump(2).c_str());
        } else {
            std::printf("Case %s: %s\n%s", opt->case_path.c_str(), c.name.c_str(), pullin_text(r).c_str());
            if (dyn) std::printf("%s", dynamic_pullin_text(*dyn).c_str());
            if (!opt->out_dir.empty()) std::printf("Written to %s/\n", opt->out_dir.c_str());
        }
        // A branch that ends before it found pull-in or touch-down has no answer to give.
        if (!r.pullin && !r.touchdown) {
            std::fprintf(stderr, "vibroimpact pullin: no pull-in and no touch-down found: %s\n", r.end.c_str());
            return kExitFailure;
        }
        return kExitOk;
    };
}

}  // namespace vi::cli
