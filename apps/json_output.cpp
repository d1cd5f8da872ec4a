#include "json_output.hpp"

#include <cmath>
#include <cstdio>

#include "io/csv_reader.hpp"

namespace vi::cli {

nlohmann::json csv_as_json(const std::string& csv_text, const std::string& name) {
    const std::vector<CsvRow> rows = split_csv(csv_text, name);
    nlohmann::json j = {{"columns", nlohmann::json::array()}, {"rows", nlohmann::json::array()}};
    if (rows.empty()) return j;
    j["columns"] = rows.front().cells;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        nlohmann::json row = nlohmann::json::array();
        for (const std::string& cell : rows[r].cells) {
            const auto v = csv_cell_number(cell);
            if (!v) {
                row.push_back(cell);
            } else if (std::isnan(*v)) {
                row.push_back(nullptr);
            } else {
                row.push_back(*v);
            }
        }
        j["rows"].push_back(std::move(row));
    }
    return j;
}

void print_json(const nlohmann::json& j) {
    // Text cells are the program's own (UTF-8); a stray byte is replaced rather than failing the output.
    std::fputs((j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n").c_str(), stdout);
}

}  // namespace vi::cli
