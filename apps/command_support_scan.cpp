// `vibroimpact support-scan CASE`: supported-beam frequency ratios as supports[0] moves (paper Fig. 8).

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "modal/support_scan.hpp"
#include "commands.hpp"
#include "json_output.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "io/output_files.hpp"
#include "io/range_spec.hpp"
#include "report/modal_output.hpp"
#include "support_model_option.hpp"

namespace vi::cli {

CommandBody add_support_scan_command(CLI::App& app) {
    struct SupportScanCommandOptions {
        std::string case_path;
        std::string positions = "0.02:1:50";
        int count = 3;
        std::string out_dir;
        std::string support_model = "pin";
        bool json = false;
    };
    auto opt = std::make_shared<SupportScanCommandOptions>();
    CLI::App* sub = app.add_subcommand(
        "support-scan", "Frequency ratios w_i/w_in of the supported beam as the first support moves (Fig. 8)");
    sub->add_option("case", opt->case_path, "Case file (TOML) with at least one support")->required();
    sub->add_option("--positions", opt->positions,
                    "Support positions x0/l: list a,b,c, range start:stop:count or log:start:stop:count")
        ->capture_default_str();
    sub->add_option("--count,-n", opt->count, "Number of bending modes")->check(CLI::Range(1, 100))->capture_default_str();
    sub->add_option("--out,-o", opt->out_dir, "Folder for support_scan.csv (otherwise CSV on stdout)");
    add_support_model_option(*sub, opt->support_model);
    sub->add_flag("--json", opt->json, "Print the scan as JSON on stdout (the columns and rows of support_scan.csv)");

    return [opt]() {
        std::vector<double> positions;
        try {
            positions = parse_range_spec(opt->positions);
        } catch (const std::invalid_argument& e) {
            throw InputError("--positions: " + std::string(e.what()));
        }
        for (double p : positions) {
            if (!(p > 0.0 && p <= 1.0)) throw InputError("--positions: every x0/l must lie in (0, 1]");
        }
        const Case c = read_case_file(opt->case_path);
        if (c.supports.empty()) throw InputError(opt->case_path + ": supports: the case has no support to move");
        std::vector<SupportScanPoint> points;
        try {
            points = support_scan(c, positions, opt->count, parse_support_model(opt->support_model));
        } catch (const InputError& e) {
            // The case was checked as read: what fails now is a position of the scan.
            throw InputError("--positions: " + std::string(e.what()));
        }
        // A coarse mesh may have fewer bending modes than asked for: report what exists.
        std::size_t count = static_cast<std::size_t>(opt->count);
        for (const auto& pt : points) count = std::min(count, pt.study.ratios.size());
        const std::string csv = support_scan_csv(points, static_cast<int>(count)).str();
        if (!opt->out_dir.empty()) write_output_files(opt->out_dir, {{"support_scan.csv", csv}});
        if (opt->json) {
            print_json(csv_as_json(csv, "support_scan.csv"));
        } else if (opt->out_dir.empty()) {
            std::fputs(csv.c_str(), stdout);
        } else {
            std::printf("Written %zu positions to %s/support_scan.csv\n", points.size(), opt->out_dir.c_str());
        }
        return kExitOk;
    };
}

}  // namespace vi::cli
