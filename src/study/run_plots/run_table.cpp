#include "study/run_plots/run_table.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <set>

#include "io/csv_reader.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"

namespace vi {

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
    const std::vector<CsvRow> rows = split_csv(*text, path);
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
            const std::optional<double> number = csv_cell_number(row.cells[k]);
            double v = number.value_or(0.0);
            if (!number) {
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
