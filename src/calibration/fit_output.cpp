#include "calibration/fit_output.hpp"

#include <algorithm>
#include <cmath>

#include "io/csv_writer.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string format(const char* f, double v) { return formatted(f, v); }

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

}  // namespace vi
