#include "study/run_plots/run_plots.hpp"

#include <filesystem>
#include <fstream>

#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "study/run_plots/run_figures.hpp"

namespace vi {
namespace {
namespace fs = std::filesystem;

bool has(const fs::path& dir, const char* file) {
    std::error_code ec;
    return fs::is_regular_file(dir / file, ec);
}

// The case's name as the folder's JSON records it (summary.json's resolved.name, sweep.json's and
// modes.json's case_name); empty when it does not (no such file, or one written before it held a name).
std::string case_name_of(const std::string& dir, RunKind kind) {
    const char* file = kind == RunKind::sweep ? "/sweep.json" : kind == RunKind::modes ? "/modes.json" : "/summary.json";
    const nlohmann::json j = read_run_json(dir + file);
    const nlohmann::json* name = nullptr;
    if (kind != RunKind::transient && j.is_object() && j.contains("case_name")) name = &j["case_name"];
    if (kind == RunKind::transient && j.is_object() && j.contains("resolved") && j["resolved"].is_object() &&
        j["resolved"].contains("name")) {
        name = &j["resolved"]["name"];
    }
    return name && name->is_string() ? name->get<std::string>() : std::string();
}

}  // namespace

const char* run_kind_name(RunKind k) {
    switch (k) {
        case RunKind::transient: return "simulate";
        case RunKind::modes: return "modes";
        case RunKind::sweep: return "sweep";
    }
    return "?";
}

RunKind run_kind(const std::string& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) throw InputError(dir + ": no such folder");
    if (has(dir, "sweep.csv")) return RunKind::sweep;
    if (has(dir, "history.csv")) return RunKind::transient;
    if (has(dir, "shapes_unsupported.csv") || has(dir, "shapes_supported.csv")) return RunKind::modes;
    throw InputError(dir + ": not a run folder: it holds none of history.csv (simulate --out), shapes_*.csv (modes --out), "
                           "sweep.csv (sweep --out)");
}

RunPlots run_plots(const std::string& dir) {
    RunPlots p;
    p.kind = run_kind(dir);
    switch (p.kind) {
        case RunKind::transient: p.figures = transient_figures(dir, p.skipped); break;
        case RunKind::modes: p.figures = modes_figures(dir); break;
        case RunKind::sweep: p.figures = sweep_figures(dir, p.skipped); break;
    }
    const std::string name = case_name_of(dir, p.kind);
    // Every figure says what it shows and of which case, so that one copied out of its folder still does.
    for (FigureSpec& f : p.figures) {
        const std::string title = name.empty() ? f.title : f.title + " - " + name;
        f.plot = "set title " + gp_quote(title) + " noenhanced\n" + f.plot;
    }
    if (p.kind == RunKind::transient) {
        for (FigureSpec& f : field_figures(dir, name)) p.figures.push_back(std::move(f));
    }
    return p;
}

nlohmann::json read_run_json(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return nullptr;
    if (!fs::is_regular_file(path, ec)) throw InputError(path + ": cannot read: not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot read: cannot open");
    // Parsed from the file as it is read, with no whole-file limit: the sweep.json of a large sweep
    // lists every value of its axes and every failed point (a million failures are some 100 MB).
    // The failures are not drawn, so they are dropped as they are parsed.
    const nlohmann::json::parser_callback_t drop_failures = [](int depth, nlohmann::json::parse_event_t event,
                                                               nlohmann::json& parsed) {
        return !(depth == 1 && event == nlohmann::json::parse_event_t::key && parsed == "failures");
    };
    try {
        return nlohmann::json::parse(in, drop_failures);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(one_line(path + ": not valid JSON: " + e.what()));
    }
}

}  // namespace vi
