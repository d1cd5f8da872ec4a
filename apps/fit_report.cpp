#include "fit_report.hpp"

#include <algorithm>
#include <cmath>

#include "calibration/fit_output.hpp"
#include "io/csv_writer.hpp"
#include "model/number_format.hpp"
#include "study/run_plots/plot_style.hpp"

namespace vi::cli {
namespace {

std::string format(const char* f, double v) { return formatted(f, v); }

}  // namespace

FigureSpec trajectory_figure(const MeasuredTrajectory& data, const FitResult& r) {
    FigureSpec f;
    f.name = "fit";
    f.title = "Measured and fitted " + data.column;
    f.caption = "The data (points) and the fitted model (line) against time, and the residual (model - data) below.";
    // A long record is drawn from the samples that shape it (plot's thinning: in each slice the
    // first, the last and each column's extremes), so a million samples make a figure gnuplot draws
    // in seconds and the tool can read back; fit_residuals.csv keeps every sample.
    const std::vector<std::size_t> rows = rows_to_draw({&data.value, &r.model, &r.residual}, data.t.size());
    CsvTable t;
    t.header = {"t_s", "data_" + data.column, "model_" + data.column, "residual_" + data.column};
    for (std::size_t k : rows) t.add_row({data.t[k], data.value[k], r.model[k], r.residual[k]});
    if (rows.size() < data.t.size()) {
        f.caption += " Drawn from " + std::to_string(rows.size()) + " of the " + std::to_string(data.t.size()) +
                     " samples (in each slice of the record the first, the last and each column's extremes); "
                     "fit_residuals.csv holds them all.";
    }
    f.data = {{"fit.csv", t.str()}};
    f.height = 800;
    f.plot = "set datafile separator ','\nset multiplot layout 2,1\nset key top right\nset xlabel 't [us]'\nset ylabel " +
             gp_quote(data.column) + " noenhanced\nplot 'fit.csv' using ($1*1e6):2 every ::1 with points pt 7 ps 0.4 title 'data', "
             "'' using ($1*1e6):3 every ::1 with lines lw 2 title 'model'\nset ylabel 'residual' noenhanced\n"
             "plot 'fit.csv' using ($1*1e6):4 every ::1 with lines title 'model - data'\nunset multiplot\n";
    return f;
}

FigureSpec feature_figure(const MeasuredFeatures& data, const FitResult& r) {
    FigureSpec f;
    f.name = "fit";
    f.title = "Fitted model against the measured features";
    f.caption = "Each feature's residual (model - value) in units of its sigma; the band is +-1 sigma, the dashed lines +-2.";
    f.data = {{"fit.csv", feature_residuals_csv(data, r)}};
    double top = 2.5;
    for (std::size_t k = 0; k < data.features.size(); ++k) top = std::max(top, 1.15 * std::abs(r.residual[k] / data.features[k].sigma));
    const std::string n = std::to_string(data.features.size());
    f.plot = "set datafile separator ','\nset key off\nset ylabel '(model - value) / sigma'\nset xtics rotate by -30 noenhanced\n"
             "set style fill transparent solid 0.2 noborder\nset xrange [-0.5:" + n + "-0.5]\nset yrange [-" + format("%.3g", top) +
             ":" + format("%.3g", top) + "]\n"
             "plot 1 with filledcurves y1=-1 lc rgb 'gray', 2 dt 2 lc rgb 'gray', -2 dt 2 lc rgb 'gray', "
             "'fit.csv' skip 1 using 0:6:xtic(1) with points pt 7 ps 1.5\n";
    return f;
}

}  // namespace vi::cli
