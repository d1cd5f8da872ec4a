#pragma once
// CSV text read back as io/csv_writer.hpp writes it, for every reader of the project's CSV files
// (run folders, figure data, measured trajectories, the Python module).

#include <cstddef>
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

// A cell as a number: any decimal or "inf" text std::from_chars reads (a leading '+' allowed), and the
// missing-value marker "nan" or an empty cell as NaN; nullopt for text that is not a number, or whose
// magnitude overflows a double (one too small for a double reads as the nearest, 0 or subnormal).
std::optional<double> csv_cell_number(std::string_view cell);

}  // namespace vi
