#pragma once
// CsvTable: a header row and numeric rows, rendered as CSV text with full double precision.

#include <string>
#include <vector>

namespace vi {

// A rectangular table of numbers; column names carry units (e.g. "t_s", "tip_m").
struct CsvTable {
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;
    // Appends a row; throws std::invalid_argument when its width differs from the header's.
    void add_row(std::vector<double> row);
    // The whole table as CSV text (17 significant digits, "nan" for NaN).
    [[nodiscard]] std::string str() const;
};

}  // namespace vi
