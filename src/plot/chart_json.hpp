#pragma once
// The data of a figure's interactive charts as JSON text, for report.html's page script.

#include <map>
#include <string>
#include <vector>

#include "plot/figure_gnuplot.hpp"

namespace vi {

// `f.charts` with each series' points read from f's CSV files: {"panels": [{title, labels, log axes,
// x range, marks, bands, series: [{label, group, style, x: [...], y: [...]}]}]}. Values that are not
// finite (or not positive on a log axis) become null, a gap. A series with several points at one x
// (a cloud of points) is split into parts of one point per x that share its legend entry. Safe to
// place inside a <script> element ('<', '>' and '&' escaped). Throws std::invalid_argument naming the
// figure when a series names a file or column the figure does not have.
std::string chart_json(const FigureSpec& f);

// chart_json of every figure that has charts, by figure name (for render_html).
std::map<std::string, std::string> figure_charts(const std::vector<FigureSpec>& figures);

}  // namespace vi
