#pragma once
// CSV text read back as io/csv_writer.hpp writes it, for every reader of the project's CSV files
// (run folders, figure data, measured trajectories, the Python module).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vi {

// One row's cells, and the line of the text it starts on (from 1).
struct CsvRow {
    std::size_t line = 0;
    std::vector<std::string> cells;
};

// Splits CSV text into rows. A quoted cell may hold commas, line breaks and doubled quotes (RFC 4180);
// blanks around an unquoted cell are dropped, as is the CR of a CRLF line end; blank lines are
// skipped, and with `comments` so are lines starting with '#'. Throws InputError("FILE:LINE: a
// quoted cell is not closed") naming `file`.
std::vector<CsvRow> split_csv(std::string_view text, const std::string& file, bool comments = false);

// Reads the CSV file at `path` block by block (never the whole file at once, and without the
// whole-file readers' 64 MiB limit: a run's history of a million samples is some 200 MB) and hands
// each row to `row` in order, with its line in the file, as split_csv splits them. Throws
// InputError("FILE: cannot read: reason") for a file that cannot be opened or is neither a regular
// file nor a pipe, "FILE:LINE: ..." for a quoted cell not closed or a row longer than 64 MiB (no table the
// tool writes has one); what `row` throws passes through.
void for_each_csv_row(const std::string& path, bool comments, const std::function<void(const CsvRow&)>& row);

// A cell as a number: any decimal or "inf" text std::from_chars reads (a leading '+' allowed), and the
// missing-value marker "nan" or an empty cell as NaN; nullopt for text that is not a number, or whose
// magnitude overflows a double (one too small for a double reads as the nearest, 0 or subnormal).
std::optional<double> csv_cell_number(std::string_view cell);

}  // namespace vi
