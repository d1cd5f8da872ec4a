#include "io/csv_reader.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "io/text_file.hpp"
#include "model/input_error.hpp"

namespace vi {

std::vector<CsvRow> split_csv(std::string_view text, const std::string& file, bool comments) {
    std::vector<CsvRow> rows;
    CsvRow row{1, {}};
    std::string cell;
    bool quoted = false;     // inside a quoted cell
    bool was_quoted = false; // the current cell had quotes: its blanks are its own
    bool any = false;        // the current line has more than blanks
    std::size_t line = 1;
    const auto end_cell = [&]() {
        row.cells.push_back(was_quoted ? cell : trimmed(cell));
        cell.clear();
        was_quoted = false;
    };
    const auto end_row = [&]() {
        end_cell();
        if (any) rows.push_back(std::move(row));
        row = CsvRow{line, {}};
        any = false;
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                cell += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                if (c == '\n') ++line;
                cell += c;
            }
            continue;
        }
        if (c == '\n') {
            ++line;
            end_row();
        } else if (comments && c == '#' && !any && row.cells.empty() && trimmed(cell).empty()) {
            while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
            cell.clear();
        } else if (c == ',') {
            end_cell();
            any = true;
        } else if (c == '"') {
            // A quote opens a quoted cell; blanks before it are dropped.
            if (!was_quoted) cell = trimmed(cell);
            quoted = was_quoted = any = true;
        } else if (c != '\r') {
            cell += c;
            if (c != ' ' && c != '\t') any = true;
        }
    }
    if (quoted) throw InputError(file + ":" + std::to_string(row.line) + ": a quoted cell is not closed");
    end_row();
    return rows;
}

std::optional<double> csv_cell_number(std::string_view cell) {
    if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::string_view s = cell;
    if (s.front() == '+') s.remove_prefix(1);
    if (s.empty() || (s.front() == '-' && cell.front() == '+')) return std::nullopt;
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ptr != s.data() + s.size()) return std::nullopt;
    if (ec == std::errc::result_out_of_range) {
        // Too small for a double: the nearest is fine; too large is not a number we can hold.
        const double near = std::strtod(std::string(s).c_str(), nullptr);
        if (std::fabs(near) < 1.0) return near;
        return std::nullopt;
    }
    if (ec != std::errc()) return std::nullopt;
    return v;
}

}  // namespace vi
