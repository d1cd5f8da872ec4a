#pragma once
// The page of a spread study, uq.html: what was varied, the spread of the figured columns with their
// yields and Sobol indices, and the figures (hist_<column>, sobol_<column>) drawn interactively
// beside their gnuplot PNGs, through the report machinery of report.html (docs/uq.md).

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "plot/figure_gnuplot.hpp"
#include "plot/report_document.hpp"

namespace vi {

// The page's blocks from uq.json (`summary`): the study, its inputs, failures, per figured column
// (`columns`) its statistics, yields and Sobol indices, and each figure of `figures` whose PNG is
// in `png` (a figure not drawn is named in a paragraph instead).
ReportDocument uq_report(const nlohmann::json& summary, const std::vector<std::string>& columns,
                         const std::vector<FigureSpec>& figures, const std::map<std::string, std::string>& png);

// uq.html: the page with the PNGs inlined and the figures' interactive charts.
std::string uq_html(const nlohmann::json& summary, const std::vector<std::string>& columns,
                    const std::vector<FigureSpec>& figures, const std::map<std::string, std::string>& png);

}  // namespace vi
