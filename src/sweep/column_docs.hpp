#pragma once
// What every result column of every sweep analysis means: one table per analysis, the one place
// they are written down. `sweep --list-columns` prints it and docs/sweeps.md's column tables are
// generated from it.

#include <string>
#include <vector>

#include "sweep/columns.hpp"

namespace vi {

// One documented column, or a family of them: names may hold <k> or <i> for a number.
struct SweepColumnDoc {
    std::vector<std::string> names;  // e.g. {"T_s", "T1_s", "T2_s"}, {"impact<k>_t_on_s"}
    std::string unit;                // as the docs show it: "s", "m, -", "count", "text"
    std::string meaning;             // one paragraph, Markdown
};

// The analysis's one-line summary (what a point computes, as which command).
std::string sweep_analysis_summary(SweepAnalysis a);

// The documented columns of `a`, in column order.
const std::vector<SweepColumnDoc>& sweep_column_docs(SweepAnalysis a);

// The doc entry a column name falls under (a <k> or <i> standing for digits), or nullptr.
const SweepColumnDoc* sweep_column_doc(SweepAnalysis a, const std::string& column);

// The Markdown table of `a` (header, separator, one row per entry; each line ends in '\n').
std::string sweep_column_table(SweepAnalysis a);

// The same as plain text for a terminal: each entry's names and unit, then its meaning indented
// and wrapped at `width` characters.
std::string sweep_column_text(SweepAnalysis a, std::size_t width = 100);

// `page` with the text between every "<!-- sweep-columns:NAME -->" line and its
// "<!-- /sweep-columns:NAME -->" replaced by sweep_column_table of that analysis. Throws
// std::invalid_argument for an unknown name or a marker without its end.
std::string with_sweep_column_tables(const std::string& page);

}  // namespace vi
