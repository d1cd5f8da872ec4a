#include "io/csv_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <system_error>

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

namespace {

// Bytes read at a time, and the longest row taken (a bound on the part of a block carried to the
// next: a file without line breaks must not be read into memory without end).
constexpr std::size_t kCsvBlockBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxCsvRowBytes = std::size_t{64} << 20;

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

// Splits `text` (complete rows) and hands its rows on, their lines counted from `first_line`.
void hand_rows(std::string_view text, const std::string& file, bool comments, std::size_t first_line,
               const std::function<void(const CsvRow&)>& row) {
    std::vector<CsvRow> rows;
    try {
        rows = split_csv(text, file, comments);
    } catch (const InputError& e) {
        // split_csv numbers the lines of the text it was given ("FILE:N: reason"): counted in the file.
        const std::string what = e.what();
        const std::size_t at = file.size() + 1, colon = what.find(':', at);
        if (what.rfind(file + ":", 0) != 0 || colon == std::string::npos) throw;
        const std::size_t n = std::stoul(what.substr(at, colon - at));
        throw InputError(file + ":" + std::to_string(n + first_line - 1) + what.substr(colon));
    }
    for (CsvRow& r : rows) {
        r.line += first_line - 1;
        row(r);
    }
}

}  // namespace

void for_each_csv_row(const std::string& path, bool comments, const std::function<void(const CsvRow&)>& row) {
    // Regular files and pipes (data from `<(...)`); a device (/dev/zero) would be read without end.
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
        !std::filesystem::is_fifo(status)) {
        throw InputError(path + ": cannot read: " +
                         (std::filesystem::is_directory(status) ? "it is a directory" : "not a regular file or a pipe"));
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        const std::string why = err != 0 ? std::generic_category().message(err) : std::string("cannot open");
        throw InputError(path + ": cannot read: " + why);
    }
    std::string pending;   // text read and not yet split: the start of a row that goes on in the next block
    std::size_t line = 1;  // the line `pending` starts on
    std::string block(kCsvBlockBytes, '\0');
    while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0) {
        pending.append(block.data(), static_cast<std::size_t>(in.gcount()));
        const std::size_t end = complete_rows_end(pending);
        if (end == 0 && pending.size() > kMaxCsvRowBytes) {
            throw InputError(path + ":" + std::to_string(line) + ": a row longer than " +
                             std::to_string(kMaxCsvRowBytes >> 20) + " MiB: not a table the tool writes or reads");
        }
        const std::string_view rows(pending.data(), end);
        hand_rows(rows, path, comments, line, row);
        line += static_cast<std::size_t>(std::count(rows.begin(), rows.end(), '\n'));
        pending.erase(0, end);
    }
    if (in.bad()) throw InputError(path + ": cannot read: read error");
    hand_rows(pending, path, comments, line, row);
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
