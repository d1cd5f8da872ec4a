// `vibroimpact modes CASE`: natural modes of the unsupported and the supported beam.

#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "model/input_error.hpp"
#include "modal/modal_analysis.hpp"
#include "report/modal_output.hpp"
#include "support_model_option.hpp"

namespace vi::cli {

CommandBody add_modes_command(CLI::App& app) {
    struct ModesCommandOptions {
        std::string case_path;
        int count = 5;
        bool json = false;
        std::string out_dir;
        std::string support_model = "pin";
    };
    auto opt = std::make_shared<ModesCommandOptions>();
    CLI::App* sub = app.add_subcommand("modes", "Natural frequencies, mode shapes, nodal points and peaks");
    sub->add_option("case", opt->case_path, "Case file (TOML)")->required();
    sub->add_option("--count,-n", opt->count, "Number of bending (and axial) modes")->check(CLI::Range(1, 1000));
    sub->add_flag("--json", opt->json, "Print one JSON document on stdout instead of tables");
    sub->add_option("--out,-o", opt->out_dir, "Folder for modes.json, frequencies.csv and shape CSVs");
    add_support_model_option(*sub, opt->support_model);

    return [opt]() {
        const Case c = read_case_file(opt->case_path);
        ModalStudy study;
        try {
            study = modal_study(c, opt->count, parse_support_model(opt->support_model));
        } catch (const InputError& e) {
            throw locate_in_case(c, e);
        }
        if (!opt->out_dir.empty()) write_output_files(opt->out_dir, modal_study_files(study));
        if (opt->json) {
            std::printf("%s\n", modal_study_json(study).dump(2).c_str());
        } else {
            std::printf("Case %s: %s\n%s", opt->case_path.c_str(), c.name.c_str(), modal_study_text(study).c_str());
            if (!opt->out_dir.empty()) std::printf("Written to %s/\n", opt->out_dir.c_str());
        }
        return kExitOk;
    };
}

}  // namespace vi::cli
