#pragma once
// CsvText: a CSV table whose cells are text, for figure data that mixes numbers with a status column.

#include <optional>
#include <string>
#include <vector>

namespace vi {

struct CsvText {
    std::vector<std::string> header;          // column names carry units, e.g. "x0_over_l", "t_us"
    std::vector<std::vector<std::string>> rows;
    // Appends a row; throws std::invalid_argument when its width differs from the header's.
    void add(std::vector<std::string> row);
    [[nodiscard]] std::string str() const;
};

// A number as a cell: 10 significant digits, "nan" for NaN or an empty optional (a value the run does
// not define; gnuplot breaks its lines there).
std::string cell(double v);
std::string cell(const std::optional<double>& v);
// Free text as a cell: commas, quotes and line breaks replaced, so every row splits on commas alone.
std::string text_cell(std::string s);

}  // namespace vi
