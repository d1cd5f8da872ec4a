// `vibroimpact stiction CASE`: whether the unloaded beam stays stuck on its adhesive supports and
// adhesive dielectric layers, and the detached length of a long cantilever lying on the substrate
// (docs/adhesion.md).

#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "model/input_error.hpp"
#include "study/stiction/stiction_output.hpp"

namespace vi::cli {

CommandBody add_stiction_command(CLI::App& app) {
    struct StictionCommandOptions {
        std::string case_path;
        bool json = false;
        std::string out_dir;
        int elements = 0;
    };
    auto opt = std::make_shared<StictionCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "stiction",
        "Stiction check: restoring force vs pull-off force at each adhesive support, the peel balance on each "
        "adhesive dielectric layer, detached length");
    sub->add_option("case", opt->case_path, "Case file (TOML) with an adhesive support or dielectric layer")->required();
    sub->add_flag("--json", opt->json, "Print one JSON document on stdout instead of text");
    sub->add_option("--out,-o", opt->out_dir, "Folder for stiction.json and stiction.csv");
    sub->add_option("--elements", opt->elements,
                    "Elements of the beam for these static checks, instead of the case's beam.elements (an adhesive "
                    "layer's settled front needs elements shorter than its attraction zone)")
        ->check(CLI::Range(1, 100000));

    return [opt]() {
        Case c = read_case_file(opt->case_path);
        if (opt->elements > 0) c.beam.elements = opt->elements;
        StictionResult r;
        try {
            r = stiction_check(c);
        } catch (const InputError& e) {
            // The element count --elements gave is the option's, not the case file's line.
            const std::string what = e.what(), key = "beam.elements: ";
            if (opt->elements > 0 && what.rfind(key, 0) == 0) {
                throw InputError("--elements " + std::to_string(opt->elements) + ": " + what.substr(key.size()));
            }
            throw locate_in_case(c, e);
        }
        if (!opt->out_dir.empty()) write_output_files(opt->out_dir, stiction_files(r));
        if (opt->json) {
            std::printf("%s\n", stiction_json(r).dump(2).c_str());
        } else {
            std::printf("Case %s: %s\n%s", opt->case_path.c_str(), c.name.c_str(), stiction_text(r).c_str());
            if (!opt->out_dir.empty()) std::printf("Written to %s/\n", opt->out_dir.c_str());
        }
        return kExitOk;
    };
}

}  // namespace vi::cli
