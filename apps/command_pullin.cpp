// `vibroimpact pullin CASE`: the static response to the electrodes' voltage, through pull-in.

#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "dynamics/pullin.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "model/input_error.hpp"
#include "report/pullin_output.hpp"

namespace vi::cli {

CommandBody add_pullin_command(CLI::App& app) {
    struct Options {
        std::string case_path;
        bool json = false;
        std::string out_dir;
        PullinOptions pullin;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand(
        "pullin", "Static pull-in: equilibria against voltage, pull-in, touch-down, release, C-V and f-V");
    sub->add_option("case", opt->case_path, "Case file (TOML) with at least one [[electrodes]]")->required();
    sub->add_option("--steps", opt->pullin.steps, "Continuation steps over the air gap of electrodes[0]")
        ->check(CLI::Range(10, 100000));
    sub->add_flag("--json", opt->json, "Print one JSON document on stdout instead of text");
    sub->add_option("--out,-o", opt->out_dir, "Folder for pullin.json, pullin_branch.csv, pullin_frequencies.csv");

    return [opt]() {
        const Case c = read_case_file(opt->case_path);
        PullinResult r;
        try {
            r = trace_pullin(c, opt->pullin);
        } catch (const InputError& e) {
            throw locate_in_case(c, e);
        }
        if (!opt->out_dir.empty()) write_output_files(opt->out_dir, pullin_files(r));
        if (opt->json) {
            std::printf("%s\n", pullin_json(r).dump(2).c_str());
        } else {
            std::printf("Case %s: %s\n%s", opt->case_path.c_str(), c.name.c_str(), pullin_text(r).c_str());
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
