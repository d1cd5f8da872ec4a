#pragma once
// The one CSV writer: every CSV file the program writes is a CsvTable (or, for the sweep's rows kept
// apart, csv_line) of cells made by the functions below (docs/architecture.md, "Output files").

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vi {

// The cell of a value the run does not define (a second impact that never came, a mode the mesh does
// not have, a failed sweep point's results) and of NaN. gnuplot breaks its lines at it (an empty cell
// it would skip, joining the points around it), and numpy.loadtxt, pandas, Python's float(), strtod
// and std::from_chars all read it as NaN.
inline constexpr std::string_view kCsvMissing = "nan";

// One cell's text, made only by the functions below so that every file formats alike.
class CsvCell {
public:
    [[nodiscard]] const std::string& text() const { return text_; }

private:
    explicit CsvCell(std::string text) : text_(std::move(text)) {}
    friend CsvCell csv_number(double v);
    friend CsvCell csv_count(std::int64_t n);
    friend CsvCell csv_text(std::string_view s);
    friend CsvCell csv_missing();
    std::string text_;
};

// A number as the shortest text that reads back to the same double ("0.1", "5e-324", "-0",
// "1.7976931348623157e+308"); NaN as kCsvMissing; infinities as "inf" and "-inf".
CsvCell csv_number(double v);
// kCsvMissing when empty.
CsvCell csv_number(const std::optional<double>& v);
// A whole number: a count, an index, a 0/1 flag.
CsvCell csv_count(std::int64_t n);
inline CsvCell csv_flag(bool b) { return csv_count(b ? 1 : 0); }
// Text as it is, or in double quotes with inner quotes doubled when it holds a comma, a quote, a line
// break or leading or trailing blanks (RFC 4180; readers that trim unquoted cells lose nothing).
CsvCell csv_text(std::string_view s);
CsvCell csv_missing();

// Cells joined by commas, without a line break (a sweep row, kept and journalled on its own).
std::string csv_line(const std::vector<CsvCell>& cells);
// Column names as a header line, without a line break (each name a text cell).
std::string csv_header_line(const std::vector<std::string>& names);

// A CSV file: a header row, then rows of the same width; "\n" ends every line.
struct CsvTable {
    // Column names with their units in them (io/csv_names.hpp): "t_s", "tip_m", "z_max".
    std::vector<std::string> header;

    // Appends a row; throws std::invalid_argument when its width differs from the header's.
    void add_row(const std::vector<CsvCell>& row);
    // A row of numbers (csv_number each).
    void add_row(const std::vector<double>& numbers);
    [[nodiscard]] std::size_t rows() const { return lines_.size(); }
    // The whole file.
    [[nodiscard]] std::string str() const;

private:
    std::vector<std::string> lines_;
};

}  // namespace vi
