#pragma once
// What the figures of a run folder share: their size and fonts, units read from column names, SI
// prefixes for the axes, ranges gnuplot accepts, and long histories thinned for drawing.

#include <cstddef>
#include <string>
#include <vector>

#include "plot/figure_gnuplot.hpp"

namespace vi {

// A column name split into the quantity and its unit (io/csv_names.hpp): "tip_velocity_m_s" ->
// {"tip velocity", "m/s"}, "x_over_l" -> {"x", "x/l"}, "z_max" -> {"z max", ""}.
struct ColumnUnit {
    std::string quantity;
    std::string unit;
};
ColumnUnit column_unit(const std::string& name);

// A unit with an SI prefix chosen so that the largest magnitude reads between 1 and 1000 ("µm" and a
// factor 1e6 for 3e-7 m). Units without prefixes (rad/s, x/l, -, none) keep factor 1.
struct DisplayUnit {
    double factor = 1.0;  // value in the display unit = SI value * factor
    std::string text;     // "µm", "kHz", "" (dimensionless)
};
DisplayUnit display_unit(const std::string& unit, double largest);

// The largest finite magnitude among the values (0 when none is finite).
double largest_magnitude(const std::vector<const std::vector<double>*>& columns);

// "quantity  [unit]", or the quantity alone for a dimensionless one.
std::string axis_label(const std::string& quantity, const DisplayUnit& u);

// A figure of the run-folder kind: 2400 x 1500 px, fonts and lines scaled 2.4 times (26 pt text,
// about 3 mm high when the figure is printed 17 cm wide).
FigureSpec run_figure(const std::string& name, const std::string& title, const std::string& caption);

// gnuplot commands for a grid, the axis labels (drawn as typed: no enhanced-text markup) and the key.
std::string gp_frame(const std::string& xlabel, const std::string& ylabel);

// "set <axis>range [lo:hi]" widened around a single value (gnuplot warns about an empty range, and a
// warning fails the rendering), or nothing when [lo, hi] is a proper range for autoscaling.
std::string gp_range(const std::string& axis, double lo, double hi);

// The finite minimum and maximum of the values (NaN, NaN when none is finite).
void finite_range(const std::vector<const std::vector<double>*>& columns, double& lo, double& hi);

// The rows worth drawing of a long table: all of them up to `limit`, otherwise in each of limit/4
// equal slices of the rows the first, the last, those where a column has its finite minimum or
// maximum, and the first where it has no value, so that every peak (an impact's force spike)
// survives and a gap stays a gap. The default: one slice per pixel column of a 2400 px figure, which
// can show no more (the figure's CSV then holds what it draws, not a copy of the run's table).
std::vector<std::size_t> rows_to_draw(const std::vector<const std::vector<double>*>& columns, std::size_t rows,
                                      std::size_t limit = 4 * 2400);

// A file-name-safe version of a column name ("impact1_peak_force_n"; "supports[0].gap" -> "supports_0_gap").
std::string safe_name(const std::string& s);

}  // namespace vi
