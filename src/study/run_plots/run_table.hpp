#pragma once
// A CSV file of a run folder (history.csv, shapes_*.csv, sweep.csv) read back as columns of numbers.

#include <cstddef>
#include <string>
#include <vector>

namespace vi {

struct RunTable {
    std::string file;                          // the path it was read from (for messages)
    std::vector<std::string> header;           // column names; the units are in the names ("t_s", "tip_m")
    std::vector<std::vector<double>> columns;  // columns[k][row]; NaN for an empty or "nan" cell and in text columns
    std::vector<bool> text;                    // column k holds a cell that is not a number (a status, a reason)
    std::size_t rows = 0;

    // The index of the column called `name`, or -1.
    [[nodiscard]] int find(const std::string& name) const;
};

// Reads the CSV file at `path` (a header row, then rows of the same width; cells may be quoted, as
// sweep.csv quotes a failed point's status). With `numbers_only`, a cell that is not a number is an
// error; otherwise its column is marked text. Throws InputError("FILE:LINE: reason") for an unreadable
// file, an empty one, a repeated column name, a row of another width or (numbers_only) a bad cell.
RunTable read_run_table(const std::string& path, bool numbers_only);

}  // namespace vi
