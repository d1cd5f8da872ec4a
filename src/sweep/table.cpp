#include "sweep/table.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>

#include "sweep/case_paths.hpp"
#include "io/number_text.hpp"

namespace vi {
namespace {

std::string number_cell(double v) { return std::isnan(v) ? std::string() : round_trip_text(v); }

std::string text_cell(const std::string& s, bool always_quote) {
    if (!always_quote && s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '"') out += '"';
        out += ch;
    }
    return out + "\"";
}

std::string cell_text(const SweepCell& c) {
    if (const auto* d = std::get_if<double>(&c)) return number_cell(*d);
    if (const auto* i = std::get_if<std::int64_t>(&c)) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%" PRId64, *i);
        return buf;
    }
    if (const auto* s = std::get_if<std::string>(&c)) return text_cell(*s, false);
    return "";
}

const char* analysis_name(SweepAnalysis a) { return a == SweepAnalysis::modes ? "modes" : "simulate"; }

}  // namespace

std::string sweep_csv_header(const SweepGrid& grid, const std::vector<SweepColumn>& columns) {
    std::string line;
    for (const SweepAxis& a : grid.axes()) {
        if (!line.empty()) line += ',';
        line += a.path.text();
    }
    for (const SweepColumn& c : columns) {
        line += ',';
        line += c.name;
    }
    return line + ",status";
}

std::string sweep_csv_row(const SweepPointResult& r, std::size_t result_columns) {
    std::string line;
    for (std::size_t i = 0; i < r.parameters.size(); ++i) {
        if (i) line += ',';
        line += number_cell(r.parameters[i]);
    }
    for (std::size_t i = 0; i < result_columns; ++i) {
        line += ',';
        if (i < r.cells.size()) line += cell_text(r.cells[i]);
    }
    return line + "," + text_cell(r.status, !r.ok());
}

std::string sweep_row_status(std::string_view row) {
    if (row.empty() || row.back() != '"') {
        const std::size_t comma = row.rfind(',');
        return std::string(comma == std::string_view::npos ? row : row.substr(comma + 1));
    }
    // A quoted last cell: walk back to its opening quote; doubled quotes inside stand for one.
    std::size_t i = row.size() - 1;
    std::string reversed;
    while (i-- > 0) {
        if (row[i] != '"') {
            reversed += row[i];
        } else if (i > 0 && row[i - 1] == '"') {
            reversed += '"';
            --i;
        } else {
            break;
        }
    }
    return std::string(reversed.rbegin(), reversed.rend());
}

nlohmann::json sweep_summary_json(const SweepGrid& grid, const SweepRunInfo& info) {
    nlohmann::json j;
    j["case"] = info.case_path;
    j["case_name"] = info.case_name;
    j["analysis"] = analysis_name(info.settings.analysis);
    if (info.settings.analysis == SweepAnalysis::modes) {
        j["modes"] = info.settings.modes;
        j["support_model"] = info.settings.support_model == SupportModel::spring ? "spring" : "pin";
    }
    nlohmann::json axes = nlohmann::json::array();
    for (const SweepAxis& a : grid.axes()) {
        axes.push_back({{"path", a.path.text()},
                        {"setting", a.setting},
                        {"unit", case_path_unit(a.path)},
                        {"values", a.values}});
    }
    j["axes"] = axes;
    j["points"] = grid.size();
    j["done"] = info.points_done;
    j["ok"] = info.points_done - info.failed;
    j["failed"] = info.failed;
    nlohmann::json failures = nlohmann::json::array();
    for (const auto& [index, status] : info.failures) failures.push_back({{"index", index}, {"status", status}});
    j["failures"] = failures;
    j["computed_this_run"] = info.computed_this_run;
    j["from_journal"] = info.from_journal;
    j["threads"] = info.threads;
    j["processes"] = info.processes;
    j["wall_s"] = info.wall_s;
    j["points_per_s"] = info.wall_s > 0.0 ? nlohmann::json(static_cast<double>(info.computed_this_run) / info.wall_s)
                                          : nlohmann::json(nullptr);
    nlohmann::json cols = nlohmann::json::array();
    for (const SweepAxis& a : grid.axes()) cols.push_back({{"name", a.path.text()}, {"unit", case_path_unit(a.path)}});
    for (const SweepColumn& c : info.columns) cols.push_back({{"name", c.name}, {"unit", c.unit}});
    cols.push_back({{"name", "status"}, {"unit", ""}});
    j["columns"] = cols;
    j["fingerprint"] = info.fingerprint;
    return j;
}

}  // namespace vi
