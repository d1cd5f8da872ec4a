#include "calibration/fit_run.hpp"

#include <cmath>
#include <cstdio>

#include "calibration/feature_fit.hpp"
#include "calibration/fit_output.hpp"
#include "calibration/trajectory_fit.hpp"
#include "io/case_reader.hpp"
#include "io/number_text.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

// A case key's error located in the case file; an error that already names its file or option as is.
InputError in_case(const Case& c, const InputError& e, const std::string& data_file) {
    const std::string what = e.what();
    const std::string key = what.substr(0, what.find(": "));
    if (key.find(':') != std::string::npos || key.rfind("-", 0) == 0 || key == data_file) return e;
    return locate_in_case(c, e);
}

FitRun run_features(const Case& c, const std::string& case_label, const FitRequest& q, const std::vector<FitParameter>& params,
                    const FitOptions& fo) {
    if (q.time_shift || q.scale || q.two_stage) {
        throw InputError(std::string(q.time_shift ? "--time-shift" : q.scale ? "--scale" : "--two-stage") +
                         ": works on a trajectory (--data), not on features");
    }
    FitRun run;
    const MeasuredFeatures& data = run.features.emplace(read_measured_features(q.features));
    check_features(c, data);
    try {
        run.results.push_back(fit_features(c, params, data, fo));
    } catch (const InputError& e) {
        throw in_case(c, e, q.features);
    }
    const FitResult& r = run.results.back();
    nlohmann::json& j = run.json;
    j = fit_result_json(params, r);
    j["features"] = {{"file", data.file}, {"count", data.features.size()}};
    j["rms_normalized_residual"] = r.rms;
    for (std::size_t k = 0; k < data.features.size(); ++k) {
        const MeasuredFeature& f = data.features[k];
        j["feature_residuals"].push_back({{"name", f.name}, {"value", f.value}, {"sigma", f.sigma}, {"model", r.model[k]},
                                          {"normalized", r.residual[k] / f.sigma}});
    }
    char head[512];
    std::snprintf(head, sizeof head, "Fit of %s to %s (%zu features): %s after %d iterations, %d simulations; rms of "
                  "(model - value) / sigma %.3g\n", case_label.c_str(), data.file.c_str(), data.features.size(),
                  r.converged ? "converged" : "NOT converged", r.iterations, r.simulations, r.rms);
    run.text = head + fit_result_text(params, r);
    run.residuals_csv = feature_residuals_csv(data, r);
    return run;
}

// Two stages: fit.json's "two_stage" part and the text of both.
void report_two_stage(FitRun& run, const std::string& case_label, const std::vector<FitParameter>& params, const TwoStageFit& two) {
    const MeasuredTrajectory& data = *run.trajectory;
    std::vector<FitParameter> p1, p2;
    for (std::size_t i : two.stage1_params) p1.push_back(params[i]);
    for (std::size_t i : two.stage2_params) p2.push_back(params[i]);
    nlohmann::json s1 = fit_result_json(p1, two.stage1), s2 = fit_result_json(p2, two.stage2);
    s1["samples"] = two.split_samples;
    s1["record_end_s"] = two.split_time;
    s2["samples"] = data.t.size();
    for (double e : two.stage2_conditional_std_error) {
        s2["std_error_given_stage1"].push_back(std::isfinite(e) ? nlohmann::json(e) : nlohmann::json(nullptr));
    }
    nlohmann::json& j = run.json;
    j["two_stage"] = {{"first_impact_s", two.split_time}, {"stage1", s1}, {"stage2", s2}};
    j["converged"] = two.stage1.converged && two.stage2.converged;
    j["estimate"] = nlohmann::json::object();
    for (std::size_t i = 0; i < params.size(); ++i) j["estimate"][params[i].name()] = two.estimate[i];
    char head[512];
    std::snprintf(head, sizeof head, "Two-stage fit of %s to %s (%zu samples, %zu before the first impact at %.6g us):\n",
                  case_label.c_str(), data.file.c_str(), data.t.size(), two.split_samples, two.split_time * 1e6);
    run.text = head;
    const auto stage = [&](const char* name, const FitResult& r, const std::vector<FitParameter>& p) {
        char line[256];
        std::snprintf(line, sizeof line, "Stage %s: %s after %d iterations, %d simulations\n", name,
                      r.converged ? "converged" : "NOT converged", r.iterations, r.simulations);
        run.text += line + fit_result_text(p, r);
    };
    stage("1 (before the first impact)", two.stage1, p1);
    stage("2 (contact parameters, whole record)", two.stage2, p2);
    run.results = {two.stage1, two.stage2};
}

FitRun run_trajectory(const Case& c, const std::string& case_label, const FitRequest& q, std::vector<FitParameter> params,
                      const FitOptions& fo) {
    const std::string column = q.column.empty() ? watched_point_name(c) + "_m" : q.column;
    check_trajectory_column(c, column);
    const std::size_t extra = (q.time_shift ? 1 : 0) + (q.scale ? 1 : 0);
    FitRun run;
    const MeasuredTrajectory& data = run.trajectory.emplace(read_measured_trajectory(q.data, column, params.size() + extra + 1));
    if (q.time_shift) params.push_back(time_shift_parameter(data.t.back() - data.t.front(), q.time_shift_range));
    if (q.scale) params.push_back(scale_parameter(q.scale_range));
    try {
        if (q.two_stage) {
            report_two_stage(run, case_label, params, fit_two_stage(c, params, data, fo));
        } else {
            run.results.push_back(fit_trajectory(c, params, data, fo));
        }
    } catch (const InputError& e) {
        throw in_case(c, e, q.data);
    }
    if (!q.two_stage) {
        const FitResult& one = run.results.back();
        run.json = fit_result_json(params, one);
        char head[512];
        std::snprintf(head, sizeof head, "Fit of %s to %s (%zu samples): %s after %d iterations, %d simulations; rms residual %s\n",
                      case_label.c_str(), data.file.c_str(), data.t.size(), one.converged ? "converged" : "NOT converged",
                      one.iterations, one.simulations, round_trip_text(one.rms).c_str());
        run.text = head + fit_result_text(params, one);
    }
    const FitResult& shown = run.shown();
    nlohmann::json& j = run.json;
    j["data"] = {{"file", data.file}, {"column", data.column}, {"samples", data.t.size()}};
    j["rms_residual"] = shown.rms;
    j["noise"] = shown.sigma_from_residuals ? nlohmann::json{{"from", "residuals"}, {"sigma", shown.sigma}}
                                            : nlohmann::json{{"from", "data sigma column"}};
    run.residuals_csv = trajectory_residuals_csv(data, shown);
    return run;
}

}  // namespace

bool FitRun::converged() const {
    for (const FitResult& r : results) {
        if (!r.converged) return false;
    }
    return true;
}

void check_fit_request(const FitRequest& q) {
    if (q.data.empty() && q.features.empty()) throw InputError("--data or --features: one is required");
    if (!q.data.empty() && !q.features.empty()) throw InputError("--data or --features: one, not both");
    if (!q.time_shift && !q.time_shift_range.empty()) throw InputError("--time-shift-range: needs --time-shift");
    if (!q.scale && !q.scale_range.empty()) throw InputError("--scale-range: needs --scale");
    if (!q.features.empty() && !q.column.empty()) throw InputError("--column: works on a trajectory (--data)");
    if (q.fit.empty()) throw InputError("--fit: at least one PATH or PATH=LOW:HIGH is needed");
}

std::vector<FitParameter> fit_parameters(const Case& c, const FitRequest& q) {
    check_fit_request(q);
    std::vector<FitParameter> params;
    for (const std::string& f : q.fit) params.push_back(parse_fit_parameter(f, c));
    check_distinct(params);
    return params;
}

FitRun run_fit(const Case& c, const std::string& case_label, const FitRequest& request, const FitOptions& o) {
    const std::vector<FitParameter> params = fit_parameters(c, request);
    return request.data.empty() ? run_features(c, case_label, request, params, o)
                                : run_trajectory(c, case_label, request, params, o);
}

}  // namespace vi
