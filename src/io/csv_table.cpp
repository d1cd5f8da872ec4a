#include "io/csv_table.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace vi {

void CsvTable::add_row(std::vector<double> row) {
    if (row.size() != header.size()) throw std::invalid_argument("CsvTable: row width differs from header");
    rows.push_back(std::move(row));
}

std::string CsvTable::str() const {
    std::string out;
    for (std::size_t i = 0; i < header.size(); ++i) {
        if (i) out += ',';
        out += header[i];
    }
    out += '\n';
    char buf[40];
    for (const auto& row : rows) {
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (i) out += ',';
            if (std::isnan(row[i])) {
                out += "nan";
            } else {
                std::snprintf(buf, sizeof buf, "%.17g", row[i]);
                out += buf;
            }
        }
        out += '\n';
    }
    return out;
}

}  // namespace vi
