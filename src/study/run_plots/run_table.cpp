#include "study/run_plots/run_table.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <set>

#include "io/csv_reader.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"

// A run folder's table is read in blocks, never whole (io/csv_reader.hpp's for_each_csv_row): a
// simulate history of a million samples is some 200 MB of text, more than any whole-file reader of
// the project takes (io/text_file.hpp's 64 MiB), and as cells of text it would take several times
// that in memory. Its rows are kept as numbers only: 8 bytes a cell.

namespace vi {
namespace {

// The rows of a table as they arrive, block by block.
class TableBuilder {
public:
    TableBuilder(RunTable& t, bool numbers_only) : t_(t), numbers_only_(numbers_only) {}

    void add(const CsvRow& row) {
        if (t_.header.empty()) {
            set_header(row);
            return;
        }
        const std::size_t width = t_.header.size();
        if (row.cells.size() != width) {
            throw InputError(t_.file + ":" + std::to_string(row.line) + ": expected " + std::to_string(width) +
                             " comma-separated cells as in the header, got " + std::to_string(row.cells.size()));
        }
        for (std::size_t k = 0; k < width; ++k) {
            const std::optional<double> number = csv_cell_number(row.cells[k]);
            double v = number.value_or(0.0);
            if (!number) {
                if (numbers_only_) {
                    throw InputError(one_line(t_.file + ":" + std::to_string(row.line) + ": " + t_.header[k] + ": '" +
                                              row.cells[k] + "' is not a number"));
                }
                t_.text[k] = true;
                v = std::numeric_limits<double>::quiet_NaN();
            }
            t_.columns[k].push_back(v);
        }
        ++t_.rows;
    }

    void finish() {
        if (t_.header.empty()) throw InputError(t_.file + ":1: empty; expected a header row and data rows");
        for (std::size_t k = 0; k < t_.header.size(); ++k) {
            if (t_.text[k]) std::fill(t_.columns[k].begin(), t_.columns[k].end(), std::numeric_limits<double>::quiet_NaN());
        }
    }

private:
    void set_header(const CsvRow& row) {
        std::set<std::string> seen;
        for (const std::string& name : row.cells) {
            if (name.empty()) {
                throw InputError(t_.file + ":" + std::to_string(row.line) + ": a column without a name in the header");
            }
            if (!seen.insert(name).second) {
                throw InputError(t_.file + ":" + std::to_string(row.line) + ": column " + name + " appears twice in the header");
            }
        }
        t_.header = row.cells;
        t_.columns.assign(t_.header.size(), {});
        t_.text.assign(t_.header.size(), false);
    }

    RunTable& t_;
    bool numbers_only_;
};

}  // namespace

int RunTable::find(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k) {
        if (header[k] == name) return static_cast<int>(k);
    }
    return -1;
}

RunTable read_run_table(const std::string& path, bool numbers_only) {
    RunTable t;
    t.file = path;
    TableBuilder builder(t, numbers_only);
    for_each_csv_row(path, false, [&](const CsvRow& row) { builder.add(row); });
    builder.finish();
    return t;
}

}  // namespace vi
