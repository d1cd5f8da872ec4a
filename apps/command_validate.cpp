// `vibroimpact validate`: regenerates docs/validation.md (or, with --paper-parameters,
// docs/paper-parameters.md) from closed forms and independent methods.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "validation/report.hpp"
#include "commands.hpp"
#include "json_output.hpp"
#include "markdown_json.hpp"
#include "progress.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "io/output_files.hpp"
#include "model/run_control.hpp"
#include "stop_signals.hpp"

namespace vi::cli {

CommandBody add_validate_command(CLI::App& app) {
    struct ValidateCommandOptions {
        std::string out;
        bool quick = false;
        bool paper_parameters = false;
        bool quiet = false;
        bool json = false;
        int threads = 0;
        std::string example = "examples/paper/free_impact_tip.toml";
        ProgressSettings progress;
        std::string switch_example = "examples/switch/cantilever_switch.toml";
    };
    auto opt = std::make_shared<ValidateCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "validate", "Validation document (docs/validation.md): the model against closed forms and independent methods");
    sub->add_option("--out,-o", opt->out, "Write the Markdown document to FILE (atomically) instead of stdout");
    sub->add_flag("--json", opt->json,
                  "Print the document's sections and tables as JSON on stdout instead of the Markdown (with --out the "
                  "Markdown file is still written)");
    sub->add_flag("--quick", opt->quick, "Skip the slow parts (exact vs CVODE on the example, the m = 200 mesh)");
    sub->add_flag("--paper-parameters", opt->paper_parameters,
                  "Write docs/paper-parameters.md instead: the parameters the paper does not give, and the Kc scan");
    sub->add_option("--case", opt->example, "The default example the transient sections run")->capture_default_str();
    sub->add_option("--switch-case", opt->switch_example,
                    "The switch whose collapse threshold section 11 checks against an independent model")
        ->capture_default_str();
    CLI::Option* quiet = sub->add_flag("--quiet,-q", opt->quiet, "No progress on stderr (--progress none)");
    quiet->excludes(add_progress_options(*sub, opt->progress));
    sub->add_option("--threads,-j", opt->threads, "Worker threads for the sections (0: every CPU this process may use)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();

    return [opt]() {
        std::filesystem::path out_path(opt->out);
        if (!opt->out.empty() && out_path.filename().empty()) throw InputError("--out: expected a file name, got a folder");
        ValidationOptions vo;
        vo.quick = opt->quick;
        vo.threads = opt->threads;
        vo.example = read_case_file(opt->example);
        vo.example_path = opt->example;
        vo.switch_example = read_case_file(opt->switch_example);
        vo.switch_example_path = opt->switch_example;
        const auto t0 = std::chrono::steady_clock::now();
        auto elapsed = [t0]() { return seconds_since(t0); };
        // The document's sections counted, and a line after each step that takes noticeable time.
        Progress sections("validate", "sections", 0, 0, opt->quiet ? ProgressStyle::none : progress_style(opt->progress),
                          opt->progress.interval_s);
        vo.progress = [&sections, elapsed](const std::string& line) {
            char at[32];
            std::snprintf(at, sizeof at, "[%6.1f s] ", elapsed());
            sections.say("validate: " + std::string(at) + line);
        };
        vo.sections_done = [&sections](std::size_t done, std::size_t total) {
            if (done == 0) {
                sections.set_total(total);
            } else {
                sections.advance();
            }
        };
        const std::string text = [&] {
            const ProgressTicker ticker(sections);
            return opt->paper_parameters ? paper_parameters_report(vo) : validation_report(vo);
        }();
        sections.finish();
        // Last chance to stop: from here the document is complete and goes out whole.
        check_run();
        if (!opt->out.empty()) {
            const std::filesystem::path dir = out_path.parent_path().empty() ? "." : out_path.parent_path();
            const CommitSection commit;
            write_output_files(dir.string(), {{out_path.filename().string(), text}});
        }
        if (opt->json) {
            nlohmann::json j = {{"document", opt->paper_parameters ? "paper-parameters" : "validation"},
                                {"quick", opt->quick},
                                {"case", opt->example},
                                {"switch_case", opt->switch_example}};
            j.update(markdown_tables_json(text));
            print_json(j);
        } else if (opt->out.empty()) {
            std::fputs(text.c_str(), stdout);
        } else {
            std::printf("Written to %s\n", opt->out.c_str());
        }
        char done[64];
        std::snprintf(done, sizeof done, "validate: done in %.1f s", elapsed());
        sections.say(done);
        return kExitOk;
    };
}

}  // namespace vi::cli
