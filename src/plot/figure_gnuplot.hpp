#pragma once
// Figures drawn by gnuplot: a figure is its data (CSV text) and the gnuplot commands that plot it;
// rendering writes both into a temporary folder, runs gnuplot there and reads back PNG and SVG.

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plot/chart_spec.hpp"

namespace vi {

// One figure. The plot commands name their data files as they are named here, relative to the
// folder the figure is written to, and set no terminal or output (rendering adds those).
struct FigureSpec {
    std::string name;     // file stem: "fig4" -> fig4.png, fig4.svg, fig4.gp
    std::string title;    // short title for the report, e.g. "Fig. 4: rebound against support position"
    std::string caption;  // what it shows and how it compares with the paper (plain text)
    std::vector<std::pair<std::string, std::string>> data;  // file name -> CSV text; the first is the main one
    std::string plot;     // gnuplot commands
    int width = 1000;     // [px]
    int height = 620;     // [px]
    double scale = 1.0;   // font size (11 pt) and line widths times this: 2.4 keeps a 2400 px figure readable in print
    std::vector<ChartPanel> charts;  // the interactive form in report.html; empty: the PNG only
    // > 0: an animation, NAME.gif (gnuplot's gif terminal, animate), each frame shown this long
    // [1/100 s]; its plot commands draw one frame per plot. No PNG or SVG then.
    int animation_delay = 0;
};

// What rendering produced for one figure.
struct RenderedFigure {
    std::string png;      // bytes (an animation: the GIF's)
    std::string svg;      // text (empty for an animation)
    std::string script;   // the stand-alone .gp file (draws both from the CSVs beside it)
};

// The gnuplot executable: `requested` if it names one (a path, or a name looked up on PATH), else
// "gnuplot" on PATH; nullopt when it cannot be found or run.
std::optional<std::string> find_gnuplot(const std::string& requested = "gnuplot");

// The stand-alone gnuplot script of a figure: PNG (pngcairo, DejaVu Sans 11 × scale) then SVG; an
// animation's: the animated GIF.
std::string gnuplot_script(const FigureSpec& f);

// Renders every figure with `gnuplot` in a temporary folder that is removed afterwards: one gnuplot
// process per thread, each drawing its share of the figures. Throws std::runtime_error with
// gnuplot's first error line (which names the figure's script) when a figure fails, or when a
// gnuplot runs for more than 10 minutes. A stop request (model/run_control.hpp) kills the gnuplot
// processes and throws StopRequested.
std::vector<RenderedFigure> render_figures(const std::string& gnuplot, const std::vector<FigureSpec>& figures, int threads);

// The files of rendered figures, name -> contents: per figure <name>.png, .svg (an animation: .gif),
// .gp and its data files; and in `png` (if given) each figure's PNG by name, for a page to embed. `rendered` is in
// the order of `figures`.
std::map<std::string, std::string> figure_files(const std::vector<FigureSpec>& figures,
                                                const std::vector<RenderedFigure>& rendered,
                                                std::map<std::string, std::string>* png = nullptr);

// Text for a gnuplot string in single quotes (quotes doubled).
std::string gp_quote(const std::string& s);

// A number for a gnuplot command or a figure's text (a range, a label's place, "x/l = 0.87" in a
// title): 10 significant digits; "NaN" when not finite. Data files use io/csv_writer.hpp instead.
std::string gp_number(double v);

}  // namespace vi
