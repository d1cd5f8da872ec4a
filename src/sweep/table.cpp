#include "sweep/table.hpp"

#include "sweep/case_paths.hpp"
#include "io/csv_writer.hpp"

namespace vi {
namespace {

CsvCell cell_of(const SweepCell& c) {
    if (const auto* d = std::get_if<double>(&c)) return csv_number(*d);
    if (const auto* i = std::get_if<std::int64_t>(&c)) return csv_count(*i);
    if (const auto* s = std::get_if<std::string>(&c)) return csv_text(*s);
    return csv_missing();
}

}  // namespace

std::string sweep_csv_header(const SweepGrid& grid, const std::vector<SweepColumn>& columns) {
    std::vector<std::string> names;
    for (const SweepAxis& a : grid.axes()) names.push_back(case_path_column(a.path));
    for (const SweepColumn& c : columns) names.push_back(c.name);
    names.emplace_back("status");
    return csv_header_line(names);
}

std::string sweep_csv_row(const SweepPointResult& r, std::size_t result_columns) {
    std::vector<CsvCell> cells;
    cells.reserve(r.parameters.size() + result_columns + 1);
    for (double p : r.parameters) cells.push_back(csv_number(p));
    for (std::size_t i = 0; i < result_columns; ++i) cells.push_back(i < r.cells.size() ? cell_of(r.cells[i]) : csv_missing());
    cells.push_back(csv_text(r.status));
    return csv_line(cells);
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
    j["analysis"] = sweep_analysis_name(info.settings.analysis);
    if (info.settings.analysis == SweepAnalysis::modes) {
        j["modes"] = info.settings.modes;
        j["support_model"] = info.settings.support_model == SupportModel::spring ? "spring" : "pin";
    }
    nlohmann::json axes = nlohmann::json::array();
    for (const SweepAxis& a : grid.axes()) {
        axes.push_back({{"path", a.path.text()},
                        {"column", case_path_column(a.path)},
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
    for (const SweepAxis& a : grid.axes()) cols.push_back({{"name", case_path_column(a.path)}, {"unit", case_path_unit(a.path)}});
    for (const SweepColumn& c : info.columns) cols.push_back({{"name", c.name}, {"unit", c.unit}});
    cols.push_back({{"name", "status"}, {"unit", ""}});
    j["columns"] = cols;
    j["fingerprint"] = info.fingerprint;
    return j;
}

}  // namespace vi
