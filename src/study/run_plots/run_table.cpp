#include "study/run_plots/run_table.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <set>

#include "io/text_file.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

// One row's cells and the line it starts on. Quoted cells may hold commas and doubled quotes.
struct CsvRow {
    std::size_t line = 0;
    std::vector<std::string> cells;
};

std::vector<CsvRow> split_rows(const std::string& text, const std::string& file) {
    std::vector<CsvRow> rows;
    CsvRow row;
    std::string cell;
    bool quoted = false;
    bool any = false;  // the current line has a character other than the line break
    std::size_t line = 1;
    row.line = 1;
    const auto end_row = [&]() {
        row.cells.push_back(trimmed(cell));
        cell.clear();
        if (any) rows.push_back(std::move(row));
        row = CsvRow{};
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
            end_row();
            row.line = ++line;
        } else if (c == ',') {
            row.cells.push_back(trimmed(cell));
            cell.clear();
            any = true;
        } else if (c == '"') {
            quoted = any = true;
        } else if (c != '\r') {
            cell += c;
            if (c != ' ' && c != '\t') any = true;
        }
    }
    if (quoted) throw InputError(file + ":" + std::to_string(row.line) + ": a quoted cell is not closed");
    end_row();
    return rows;
}

// The cell as a number; false when it is not one (an empty cell is NaN, a number).
bool parse_number(const std::string& s, double& v) {
    if (s.empty()) {
        v = std::numeric_limits<double>::quiet_NaN();
        return true;
    }
    errno = 0;
    char* stop = nullptr;
    v = std::strtod(s.c_str(), &stop);
    return stop == s.c_str() + s.size() && (errno == 0 || std::fabs(v) < 1.0);  // underflow to a tiny value is fine
}

}  // namespace

int RunTable::find(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k) {
        if (header[k] == name) return static_cast<int>(k);
    }
    return -1;
}

RunTable read_run_table(const std::string& path, bool numbers_only) {
    std::string reason;
    const std::optional<std::string> text = file_text(path, reason);
    if (!text) throw InputError(path + ": cannot read: " + reason);
    const std::vector<CsvRow> rows = split_rows(*text, path);
    if (rows.empty()) throw InputError(path + ":1: empty; expected a header row and data rows");
    RunTable t;
    t.file = path;
    t.header = rows.front().cells;
    std::set<std::string> seen;
    for (const std::string& name : t.header) {
        if (name.empty()) throw InputError(path + ":" + std::to_string(rows.front().line) + ": a column without a name in the header");
        if (!seen.insert(name).second) {
            throw InputError(path + ":" + std::to_string(rows.front().line) + ": column " + name + " appears twice in the header");
        }
    }
    const std::size_t width = t.header.size();
    t.columns.assign(width, {});
    t.text.assign(width, false);
    t.rows = rows.size() - 1;
    for (auto& c : t.columns) c.reserve(t.rows);
    for (std::size_t r = 1; r < rows.size(); ++r) {
        const CsvRow& row = rows[r];
        if (row.cells.size() != width) {
            throw InputError(path + ":" + std::to_string(row.line) + ": expected " + std::to_string(width) +
                             " comma-separated cells as in the header, got " + std::to_string(row.cells.size()));
        }
        for (std::size_t k = 0; k < width; ++k) {
            double v = 0.0;
            if (!parse_number(row.cells[k], v)) {
                if (numbers_only) {
                    throw InputError(one_line(path + ":" + std::to_string(row.line) + ": " + t.header[k] + ": '" + row.cells[k] +
                                              "' is not a number"));
                }
                t.text[k] = true;
                v = std::numeric_limits<double>::quiet_NaN();
            }
            t.columns[k].push_back(v);
        }
    }
    for (std::size_t k = 0; k < width; ++k) {
        if (t.text[k]) std::fill(t.columns[k].begin(), t.columns[k].end(), std::numeric_limits<double>::quiet_NaN());
    }
    return t;
}

}  // namespace vi
