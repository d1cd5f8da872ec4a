#include "markdown_json.hpp"

#include <cctype>
#include <cmath>
#include <sstream>
#include <vector>

#include "io/csv_reader.hpp"

namespace vi::cli {
namespace {

// The cells of a table line "| a | b \| c |", a bar written "\|" inside a cell being part of it.
std::vector<std::string> cells_of(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    for (std::size_t i = 1; i < line.size(); ++i) {
        if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
            cell += '|';
            ++i;
        } else if (line[i] == '|') {
            const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
            cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
            cell.clear();
        } else {
            cell += line[i];
        }
    }
    return cells;
}

nlohmann::json cell_json(const std::string& cell) {
    if (cell == "n/a") return nullptr;
    const auto v = csv_cell_number(cell);
    if (!v) return cell;
    if (std::isnan(*v)) return nullptr;
    if (std::isinf(*v)) return cell;  // JSON has no infinity: kept as the document writes it
    return *v;
}

bool is_rule(const std::vector<std::string>& cells) {
    for (const std::string& c : cells) {
        if (c.find_first_not_of("-:") != std::string::npos || c.empty()) return false;
    }
    return !cells.empty();
}

nlohmann::json section(const std::string& heading) {
    nlohmann::json s = {{"number", nullptr}, {"title", heading}, {"tables", nlohmann::json::array()}};
    std::size_t digits = 0;
    while (digits < heading.size() && std::isdigit(static_cast<unsigned char>(heading[digits]))) ++digits;
    if (digits > 0 && heading.compare(digits, 2, ". ") == 0) {
        s["number"] = std::stoi(heading.substr(0, digits));
        s["title"] = heading.substr(digits + 2);
    }
    return s;
}

}  // namespace

nlohmann::json markdown_tables_json(const std::string& markdown) {
    nlohmann::json doc = {{"title", ""}, {"sections", nlohmann::json::array()}};
    nlohmann::json* table = nullptr;  // the table the previous line belonged to
    std::istringstream in(markdown);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("# ", 0) == 0) {
            doc["title"] = line.substr(2);
        } else if (line.rfind("## ", 0) == 0) {
            doc["sections"].push_back(section(line.substr(3)));
        }
        if (line.empty() || line.front() != '|' || doc["sections"].empty()) {
            table = nullptr;
            continue;
        }
        const std::vector<std::string> cells = cells_of(line);
        if (table == nullptr) {
            nlohmann::json& tables = doc["sections"].back()["tables"];
            tables.push_back({{"columns", cells}, {"rows", nlohmann::json::array()}});
            table = &tables.back();
        } else if (!is_rule(cells)) {
            nlohmann::json row = nlohmann::json::array();
            for (const std::string& c : cells) row.push_back(cell_json(c));
            (*table)["rows"].push_back(std::move(row));
        }
    }
    return doc;
}

}  // namespace vi::cli
