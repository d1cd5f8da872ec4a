#pragma once
// Checks that a CSV file the program wrote follows the one convention (docs/architecture.md, "Output
// files"): every header name carries its unit or is a dimensionless name (io/csv_names.hpp), every
// row has the header's width, and every cell of a number column is a number written as its shortest
// round-trip text, or the missing-value marker "nan".

#include <cstddef>
#include <string>

namespace vi::test {

// True for a column of text: a status, a reason, a stage, a kind, a law, a verdict, a solver, a
// feature's name, a spread study's input path, a list of nodal points (nodes_supported_<i>_over_l). Such cells may be empty or
// quoted; others may not.
bool is_text_column(const std::string& name);

// Adds a GoogleTest failure, naming the file, line and column, for every break of the convention.
void expect_csv_convention(const std::string& path);

// expect_csv_convention for every *.csv under dir (recursively); returns how many files it checked.
std::size_t expect_csv_convention_in(const std::string& dir);

}  // namespace vi::test
