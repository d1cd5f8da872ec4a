#pragma once
// The paper study's figures (Figs. 2-11) as gnuplot figure specs, each with the CSV it is drawn from.

#include <vector>

#include "io/csv_writer.hpp"
#include "study/paper/study.hpp"
#include "plot/figure_gnuplot.hpp"
#include "model/number_format.hpp"

namespace vi {

// Figs. 2 to 11 in order: fig2 ... fig11, each with fig<N>.csv (and a second CSV where one table
// cannot hold it: fig2_points.csv, fig3_impacts.csv).
std::vector<FigureSpec> paper_figures(const PaperStudy& study);

// Pieces shared by the two figure sources; not a stable interface.
namespace figure_detail {

// Colours of series 1..5 (gnuplot `word(colors, i)`), and the command that defines them.
inline constexpr const char* kColors = "#1f77b4 #d62728 #2ca02c #9467bd #ff7f0e";
std::string colors_command();

// The i-th of kColors (from 1, cycling), for the interactive charts.
std::string color(int i);
// One interactive series: column y against column x of the figure's first CSV.
ChartSeries series(std::string label, std::string x, std::string y, ChartSeries::Style style = ChartSeries::Style::lines,
                   std::string colour = "");
// The paper's particular points x0/l = 0.67, 0.78, 0.87, as dashed lines of a chart.
std::vector<double> particular_marks();

// Vertical dashed lines at the paper's particular points x0/l = 0.67, 0.78, 0.87, labelled at the top.
std::string particular_points();
// The x range of the support-position transient scans.
std::string scan_xrange(const PaperStudy& st);

// "%.4g" of a number, for captions and labels; us(): seconds as microseconds, 4 digits.
std::string us(double seconds);

// Of a scan: " N runs failed (...)." or ""; how many runs ended before T_p; a point's status cell
// (its T_p reason, or "error: ..."); the prefix of a scan's columns in a figure's CSV ("m50_").
std::string failures(const TransientScan& s);
int unsettled(const TransientScan& s);
CsvCell status(const TransientPoint& p);
std::string mesh_prefix(int elements);

// The figures, one function each.
FigureSpec fig2(const PaperStudy& st);
FigureSpec fig3(const PaperStudy& st);
FigureSpec fig4(const PaperStudy& st);
FigureSpec fig5(const PaperStudy& st);
FigureSpec fig6(const PaperStudy& st);
FigureSpec fig7(const PaperStudy& st);
FigureSpec fig8(const PaperStudy& st);
FigureSpec fig9(const PaperStudy& st);
FigureSpec fig10(const PaperStudy& st);
FigureSpec fig11(const PaperStudy& st);

}  // namespace figure_detail
}  // namespace vi
