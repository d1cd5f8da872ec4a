#include "study/run_plots/run_table.hpp"

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/csv_reader.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"

// A run folder's table is read in blocks, never whole: a simulate history of a million samples is
// some 200 MB of text, more than any whole-file reader of the project takes (io/text_file.hpp's
// 64 MiB), and as cells of text it would take several times that in memory. Each block's complete
// rows are split (io/csv_reader.hpp, so quoting and line numbers are those of every other reader)
// and kept as numbers only: 8 bytes a cell.

namespace vi {
namespace {

// Bytes read at a time, and the longest row taken (a bound on the carried part of a block: a file
// without line breaks must not be read into memory without end).
constexpr std::size_t kBlockBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxRowBytes = std::size_t{64} << 20;

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

// Where the complete rows of `text` end: just after its last line break outside a quoted cell (a
// doubled quote inside one toggles twice), or 0 when there is none.
std::size_t complete_rows_end(std::string_view text) {
    bool quoted = false;
    std::size_t end = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '"') quoted = !quoted;
        if (text[i] == '\n' && !quoted) end = i + 1;
    }
    return end;
}

// Splits `text` (complete rows) and hands its rows to `b`, numbering lines from `first_line`.
void add_rows(TableBuilder& b, std::string_view text, const std::string& file, std::size_t first_line) {
    std::vector<CsvRow> rows;
    try {
        rows = split_csv(text, file);
    } catch (const InputError& e) {
        // split_csv numbers the lines of the text it was given ("FILE:N: reason"): counted in the file.
        const std::string what = e.what();
        const std::size_t at = file.size() + 1, colon = what.find(':', at);
        if (what.rfind(file + ":", 0) != 0 || colon == std::string::npos) throw;
        const std::size_t n = std::stoul(what.substr(at, colon - at));
        throw InputError(file + ":" + std::to_string(n + first_line - 1) + what.substr(colon));
    }
    for (CsvRow& row : rows) {
        row.line += first_line - 1;
        b.add(row);
    }
}

}  // namespace

int RunTable::find(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k) {
        if (header[k] == name) return static_cast<int>(k);
    }
    return -1;
}

RunTable read_run_table(const std::string& path, bool numbers_only) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
        throw InputError(path + ": cannot read: not a regular file");
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        const std::string why = err != 0 ? std::generic_category().message(err) : std::string("cannot open");
        throw InputError(path + ": cannot read: " + why);
    }
    RunTable t;
    t.file = path;
    TableBuilder builder(t, numbers_only);
    std::string pending;    // text read and not yet split: the start of a row that goes on in the next block
    std::size_t line = 1;   // the line `pending` starts on
    std::string block(kBlockBytes, '\0');
    while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0) {
        pending.append(block.data(), static_cast<std::size_t>(in.gcount()));
        const std::size_t end = complete_rows_end(pending);
        if (end == 0 && pending.size() > kMaxRowBytes) {
            throw InputError(path + ":" + std::to_string(line) + ": a row longer than " + std::to_string(kMaxRowBytes >> 20) +
                             " MiB: not a table the tool writes");
        }
        const std::string_view rows(pending.data(), end);
        add_rows(builder, rows, path, line);
        line += static_cast<std::size_t>(std::count(rows.begin(), rows.end(), '\n'));
        pending.erase(0, end);
    }
    if (in.bad()) throw InputError(path + ": cannot read: read error");
    add_rows(builder, pending, path, line);
    builder.finish();
    return t;
}

}  // namespace vi
