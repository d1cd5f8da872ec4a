// `vibroimpact new KIND [--out FILE]`: a complete, commented starter case for one's own device.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "io/output_files.hpp"
#include "model/input_error.hpp"
#include "starter_cases.hpp"
#include "stop_signals.hpp"

namespace vi::cli {

CommandBody add_new_command(CLI::App& app) {
    struct NewCommandOptions {
        std::string kind;
        std::string out;
        bool force = false;
    };
    auto opt = std::make_shared<NewCommandOptions>();
    std::vector<std::string> kinds;
    std::string listing;
    for (const StarterCase& s : starter_cases()) {
        kinds.emplace_back(s.kind);
        listing.append("\n  ").append(s.kind).append(" (").append(s.example).append(")");
    }
    CLI::App* sub = app.add_subcommand("new", "Write a complete, commented starter case to edit for one's own device");
    sub->add_option("kind", opt->kind, "What to start from:" + listing)->required()->check(CLI::IsMember(kinds));
    sub->add_option("--out,-o", opt->out, "Case file to write (default: print it on stdout)");
    sub->add_flag("--force", opt->force, "Overwrite --out if it exists");

    return [opt]() {
        const StarterCase* found = nullptr;
        for (const StarterCase& s : starter_cases()) {
            if (s.kind == opt->kind) found = &s;
        }
        std::string text = "# Written by `vibroimpact new ";
        text.append(found->kind).append("` (the example ").append(found->example);
        text.append("): edit the values for your device; docs/case-files.md lists every key.\n");
        text.append(found->text);
        if (opt->out.empty()) {
            std::fwrite(text.data(), 1, text.size(), stdout);
            return kExitOk;
        }
        if (std::filesystem::exists(opt->out) && !opt->force) {
            throw InputError("--out " + opt->out + ": the file exists (--force overwrites it)");
        }
        const std::filesystem::path path(opt->out);
        const std::string dir = path.has_parent_path() ? path.parent_path().string() : ".";
        {
            const CommitSection commit;
            write_output_files(dir, {{path.filename().string(), text}});
        }
        std::printf("Wrote %s (%s); run it with: vibroimpact simulate %s\n", opt->out.c_str(), std::string(found->kind).c_str(),
                    opt->out.c_str());
        return kExitOk;
    };
}

}  // namespace vi::cli
