#include "fit_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/csv_writer.hpp"
#include "study/run_plots/plot_style.hpp"

namespace vi::cli {
namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string format(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

// Whether x lies on `bound`: within 1e-6 of the parameter's scale and within 1e-6 of the values'
// own size. The second keeps a wide range (10:1e10, a scale of 1e10) from calling an estimate of
// 1000 "on its lower bound" 10; Ceres puts an estimate it holds at a bound exactly on it.
bool on_bound(const FitParameter& p, double x, double bound) {
    const double gap = std::abs(x - bound);
    return gap <= 1e-6 * p.scale() && gap <= 1e-6 * std::max(std::abs(x), std::abs(bound));
}

// "low" or "high" when the estimate sits on a bound, else "".
std::string at_bound(const FitParameter& p, double x) {
    if (p.low && on_bound(p, x, *p.low)) return "low";
    if (p.high && on_bound(p, x, *p.high)) return "high";
    return "";
}

}  // namespace

nlohmann::json fit_result_json(const std::vector<FitParameter>& params, const FitResult& r) {
    nlohmann::json j;
    j["converged"] = r.converged;
    j["message"] = r.message;
    j["iterations"] = r.iterations;
    j["simulations"] = r.simulations;
    j["cost"] = r.cost;
    j["parameters"] = nlohmann::json::array();
    for (std::size_t i = 0; i < params.size(); ++i) {
        nlohmann::json p;
        p["path"] = params[i].name();
        p["nuisance"] = params[i].nuisance();
        p["start"] = params[i].start;
        p["bounds"] = {params[i].low ? nlohmann::json(*params[i].low) : nlohmann::json(nullptr),
                       params[i].high ? nlohmann::json(*params[i].high) : nlohmann::json(nullptr)};
        p["estimate"] = r.estimate[i];
        p["std_error"] = number_or_null(r.std_error[i]);
        p["ci95"] = {number_or_null(r.ci_low[i]), number_or_null(r.ci_high[i])};
        p["determined"] = r.undetermined[i].empty();
        if (!r.undetermined[i].empty()) p["why_undetermined"] = r.undetermined[i];
        if (!at_bound(params[i], r.estimate[i]).empty()) p["at_bound"] = at_bound(params[i], r.estimate[i]);
        j["parameters"].push_back(p);
    }
    for (Eigen::Index a = 0; a < r.correlation.rows(); ++a) {
        nlohmann::json row = nlohmann::json::array();
        for (Eigen::Index b = 0; b < r.correlation.cols(); ++b) row.push_back(number_or_null(r.correlation(a, b)));
        j["correlation"].push_back(row);
    }
    j["best_start"] = r.best;
    j["distinct_minima"] = r.distinct_minima;
    for (const StartRun& s : r.starts) {
        j["starts"].push_back({{"start", s.start},
                               {"end", s.end},
                               {"cost", number_or_null(s.cost)},
                               {"converged", s.converged},
                               {"minimum", s.minimum < 0 ? nlohmann::json(nullptr) : nlohmann::json(s.minimum)},
                               {"iterations", s.iterations},
                               {"simulations", s.simulations},
                               {"message", s.message}});
    }
    return j;
}

std::string fit_result_text(const std::vector<FitParameter>& params, const FitResult& r) {
    std::string out;
    for (std::size_t i = 0; i < params.size(); ++i) {
        const std::string name = params[i].name() + (params[i].nuisance() ? " (nuisance)" : "");
        if (r.undetermined[i].empty()) {
            out += "  " + name + " = " + format("%.6g", r.estimate[i]) + " +- " + format("%.3g", r.std_error[i]) + " (95 %: " +
                   format("%.6g", r.ci_low[i]) + " .. " + format("%.6g", r.ci_high[i]) + ")";
        } else {
            out += "  " + name + " = " + format("%.6g", r.estimate[i]) + ": NOT determined by the data (" + r.undetermined[i] + ")";
        }
        const std::string bound = at_bound(params[i], r.estimate[i]);
        if (!bound.empty()) out += "; AT ITS " + std::string(bound == "low" ? "LOWER" : "UPPER") + " BOUND (the data pull beyond it; the interval assumes a minimum inside)";
        out += "\n";
    }
    if (r.starts.size() <= 1) return out;
    int converged = 0;
    for (const StartRun& s : r.starts) converged += s.converged ? 1 : 0;
    out += "  Starts: " + std::to_string(r.starts.size()) + ", " + std::to_string(converged) + " converged, best start " +
           std::to_string(r.best + 1) + "; " +
           (r.distinct_minima > 1 ? std::to_string(r.distinct_minima) + " DISTINCT minima found (minimum 0 is the best)"
                                  : std::string("one minimum found")) + "\n";
    out += "    start  end cost      converged  minimum  start values -> end values\n";
    for (std::size_t k = 0; k < r.starts.size(); ++k) {
        const StartRun& s = r.starts[k];
        std::string line = "    " + format("%5.0f", static_cast<double>(k + 1)) + "  " + format("%-12.6g", s.cost) + "  " +
                           (s.converged ? "yes      " : "no       ") + "  " +
                           (s.minimum < 0 ? std::string("-      ") : format("%-7.0f", s.minimum)) + "  ";
        for (std::size_t i = 0; i < s.start.size(); ++i) line.append(i ? " " : "").append(format("%.4g", s.start[i]));
        line.append(" ->");
        for (double v : s.end) line.append(" ").append(format("%.6g", v));
        out.append(line).append("\n");
    }
    return out;
}

std::string trajectory_residuals_csv(const MeasuredTrajectory& data, const FitResult& r) {
    CsvTable t;
    t.header = {"t_s", "data_" + data.column, "model_" + data.column, "residual_" + data.column};
    for (std::size_t k = 0; k < data.t.size(); ++k) t.add_row({data.t[k], data.value[k], r.model[k], r.residual[k]});
    return t.str();
}

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

std::string feature_residuals_csv(const MeasuredFeatures& data, const FitResult& r) {
    CsvTable t;
    t.header = {"feature", "value_in_feature_unit", "sigma_in_feature_unit", "model_in_feature_unit", "residual_in_feature_unit",
                "residual_over_sigma"};
    for (std::size_t k = 0; k < data.features.size(); ++k) {
        const MeasuredFeature& f = data.features[k];
        t.add_row({csv_text(f.name), csv_number(f.value), csv_number(f.sigma), csv_number(r.model[k]), csv_number(r.residual[k]),
                   csv_number(r.residual[k] / f.sigma)});
    }
    return t.str();
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
