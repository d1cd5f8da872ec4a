#include "io/csv_writer.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "io/number_text.hpp"

namespace vi {

CsvCell csv_number(double v) { return std::isnan(v) ? csv_missing() : CsvCell(round_trip_text(v)); }

CsvCell csv_number(const std::optional<double>& v) { return v ? csv_number(*v) : csv_missing(); }

CsvCell csv_count(std::int64_t n) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, n);
    return CsvCell(std::string(buf, r.ptr));
}

CsvCell csv_text(std::string_view s) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    const bool quote = s.find_first_of(",\"\r\n") != std::string_view::npos || (!s.empty() && (blank(s.front()) || blank(s.back())));
    if (!quote) return CsvCell(std::string(s));
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return CsvCell(out + "\"");
}

CsvCell csv_missing() { return CsvCell(std::string(kCsvMissing)); }

std::string csv_line(const std::vector<CsvCell>& cells) {
    std::string out;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (i) out += ',';
        out += cells[i].text();
    }
    return out;
}

std::string csv_header_line(const std::vector<std::string>& names) {
    std::vector<CsvCell> cells;
    cells.reserve(names.size());
    for (const std::string& n : names) cells.push_back(csv_text(n));
    return csv_line(cells);
}

void CsvTable::add_row(const std::vector<CsvCell>& row) {
    if (row.size() != header.size()) {
        throw std::invalid_argument("CSV row of " + std::to_string(row.size()) + " cells under a header of " +
                                    std::to_string(header.size()) + " columns");
    }
    lines_.push_back(csv_line(row));
}

void CsvTable::add_row(const std::vector<double>& numbers) {
    std::vector<CsvCell> row;
    row.reserve(numbers.size());
    for (double v : numbers) row.push_back(csv_number(v));
    add_row(row);
}

std::string CsvTable::str() const {
    std::string out = csv_header_line(header) + "\n";
    for (const std::string& line : lines_) out.append(line).append("\n");
    return out;
}

}  // namespace vi
