#include "report/csv_text.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace vi {

void CsvText::add(std::vector<std::string> row) {
    if (row.size() != header.size()) throw std::invalid_argument("CsvText: row width differs from header");
    rows.push_back(std::move(row));
}

std::string CsvText::str() const {
    std::string out;
    auto line = [&](const std::vector<std::string>& cells) {
        for (std::size_t i = 0; i < cells.size(); ++i) {
            if (i) out += ',';
            out += cells[i];
        }
        out += '\n';
    };
    line(header);
    for (const auto& r : rows) line(r);
    return out;
}

std::string cell(double v) {
    if (!std::isfinite(v)) return "nan";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string cell(const std::optional<double>& v) { return v ? cell(*v) : std::string("nan"); }

std::string text_cell(std::string s) {
    for (char& c : s) {
        if (c == ',') c = ';';
        if (c == '"') c = '\'';
        if (c == '\n' || c == '\r') c = ' ';
    }
    return s;
}

}  // namespace vi
