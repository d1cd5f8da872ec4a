// `vibroimpact cycles CASE --cycles N`: the switch driven through N actuation cycles by its
// electrodes' waveform repeated every period; per cycle the bounces, contact energy, peaks, yield and
// wear, and their trend (docs/cycles.md).

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "progress.hpp"
#include "io/case_reader.hpp"
#include "io/output_files.hpp"
#include "io/units.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"
#include "model/run_control.hpp"
#include "stop_signals.hpp"
#include "study/cycles/cycles.hpp"
#include "study/cycles/cycles_output.hpp"

namespace vi::cli {
namespace {

// --cycles TEXT: a whole number from 1 to kMaxCycles; anything else (a fraction, 1e9, text) is one
// line naming the limit.
int parse_cycles(const std::string& text) {
    const std::string limit = ": must be a whole number from 1 to " + std::to_string(kMaxCycles) + " (the most one study runs)";
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        throw InputError("--cycles " + in_quotes(text) + limit);
    }
    if (used != text.size() || !(v >= 1.0 && v <= kMaxCycles) || v != std::floor(v)) {
        throw InputError("--cycles " + text + limit);
    }
    return static_cast<int>(v);
}

}  // namespace

CommandBody add_cycles_command(CLI::App& app) {
    struct CyclesCommandOptions {
        std::string case_path;
        std::string cycles;
        std::string period;
        bool json = false;
        std::string out_dir;
        ProgressSettings progress;
    };
    auto opt = std::make_shared<CyclesCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "cycles", "Actuation cycles: the voltage waveform repeated N times; bounces, contact energy and wear per cycle");
    sub->add_option("case", opt->case_path, "Case file (TOML) with electrodes whose waveform ends within the period")
        ->required();
    sub->add_option("--cycles,-n", opt->cycles, "Number of actuation cycles N (1 to " + std::to_string(kMaxCycles) + ")")
        ->required();
    sub->add_option("--period", opt->period, "One cycle's length (e.g. \"100 us\"); default: the case's solver.horizon");
    sub->add_flag("--json", opt->json, "Print cycles.json on stdout instead of a summary");
    sub->add_option("--out,-o", opt->out_dir, "Folder for cycles.csv and cycles.json");
    add_progress_options(*sub, opt->progress);

    return [opt]() {
        CycleSettings s;
        s.cycles = parse_cycles(opt->cycles);
        if (!opt->period.empty()) {
            try {
                s.period = parse_quantity(opt->period, Dimension::time);
            } catch (const std::invalid_argument& e) {
                throw InputError("--period " + in_quotes(opt->period) + ": " + e.what());
            }
            if (!(s.period > 0.0)) throw InputError("--period " + in_quotes(opt->period) + ": must be above 0 s");
        }
        const Case c = read_case_file(opt->case_path);
        const ProgressStyle style = progress_style(opt->progress);
        CyclesResult r;
        try {
            Progress progress("cycles", "cycles", static_cast<std::size_t>(s.cycles), 0, style, opt->progress.interval_s);
            const ProgressTicker ticker(progress);
            int shown = 0;
            r = run_cycles(c, s, [&](int done) {
                if (done > shown) progress.advance(static_cast<std::size_t>(done - shown));
                shown = done;
            });
        } catch (const InputError& e) {
            throw locate_in_case(c, e);
        }
        const OutputFiles files = cycles_files(r);
        check_run();
        if (!opt->out_dir.empty()) {
            const CommitSection commit;
            write_output_files(opt->out_dir, files);
        }
        if (opt->json) {
            std::fputs(files.at("cycles.json").c_str(), stdout);
            return kExitOk;
        }
        std::printf("Case %s: %s\n%s", opt->case_path.c_str(), c.name.c_str(), cycles_text(r).c_str());
        if (!opt->out_dir.empty()) std::printf("Written to %s/ (cycles.csv, cycles.json)\n", opt->out_dir.c_str());
        return kExitOk;
    };
}

}  // namespace vi::cli
