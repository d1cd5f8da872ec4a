#pragma once
// The figures of a spread study: a histogram of a result column with its specs' bounds, and a bar
// chart of its first-order and total Sobol indices per input with their intervals (docs/uq.md).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "plot/figure_gnuplot.hpp"
#include "uq/sample_design.hpp"
#include "uq/uq_summary.hpp"

namespace vi {

// For each of `columns` (numeric columns of the table): "hist_<column>" (the base runs' values in
// Freedman-Diaconis bins, 5 to 100 of them, each spec on the column a vertical line) and, when
// `summary` holds its Sobol indices, "sobol_<column>" (inputs by falling total index). Columns
// without a value get no figure.
std::vector<FigureSpec> uq_figures(const nlohmann::json& summary, const UqTable& table, const SampleDesign& design,
                                   const std::vector<YieldSpec>& specs, const std::vector<std::string>& columns);

}  // namespace vi
