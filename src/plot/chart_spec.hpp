#pragma once
// The interactive form of a figure: panels of x-y series taken from columns of the figure's CSV
// files, drawn in report.html by the vendored uPlot (third_party/uplot) beside gnuplot's PNG.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vi {

// One curve or set of points: column `y` against column `x` of one of the figure's CSV files.
struct ChartSeries {
    // bars: one bar from 0 to y per row, spanning x to x_to, or bar_width centred on x.
    enum class Style { lines, points, linespoints, bars };
    std::string label;                 // legend text, e.g. "mode 2"
    std::string x;                     // column names as in the CSV header, e.g. "x0_over_l"
    std::string y;
    std::string file;                  // data file name of the FigureSpec; empty: its first
    std::vector<std::pair<std::string, std::string>> where;  // only rows whose column (first) holds this text (second)
    double x_scale = 1.0;              // plotted x = x_scale * column x (e.g. 1e3 for [10^-3])
    double x_offset = 0.0;             // added to the plotted x (bars side by side)
    double y_scale = 1.0;
    bool abs_y = false;                // plot |y|
    std::string x_to;                  // bars: column of each bar's right end; empty: bar_width about x
    double bar_width = 0.8;            // bars without x_to: their width [x units]
    std::string y_low, y_high;         // columns of an interval bar at each point (a confidence interval); empty: none
    Style style = Style::lines;
    bool dashed = false;
    bool right_axis = false;           // on the right-hand y axis (the panel's y2_label)
    std::string color;                 // "#1f77b4"; empty: the next colour of the page's palette
    std::string group;                 // series with the same non-empty group share one legend entry
};

// One x-y chart (a panel of the gnuplot figure).
struct ChartPanel {
    std::string title;                 // e.g. "(a) displacement peaks"; may be empty
    std::string x_label;               // with units, e.g. "support position x0/l [-]"
    std::string y_label;
    std::string y2_label;              // right-hand axis; empty: none
    bool log_x = false;
    bool log_y = false;
    std::optional<double> x_min;       // initial x range; unset: the data's
    std::optional<double> x_max;
    std::vector<double> x_marks;       // dashed vertical lines (e.g. the paper's particular points)
    std::vector<std::pair<double, double>> x_bands;  // shaded x intervals (e.g. contact episodes)
    std::vector<std::pair<double, std::string>> x_ticks;  // labelled x ticks (categories); empty: numbers
    std::vector<ChartSeries> series;
};

}  // namespace vi
