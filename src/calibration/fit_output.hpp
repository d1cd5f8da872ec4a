#pragma once
// What a fit reports (docs/calibration.md): fit.json's parts, the text summary and the residual
// tables of a trajectory or feature fit.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calibration/least_squares.hpp"
#include "io/measured_features.hpp"
#include "io/measured_trajectory.hpp"

namespace vi {

// One fit's (or one stage's) outcome: convergence, the parameters with their uncertainty, the
// correlation matrix and the table of starts.
nlohmann::json fit_result_json(const std::vector<FitParameter>& params, const FitResult& r);

// The same as text lines: the parameters (nuisance ones marked), then the starts when there were several.
std::string fit_result_text(const std::vector<FitParameter>& params, const FitResult& r);

// t_s, data_<column>, model_<column>, residual_<column> per sample (the column's unit in its name: tip_m).
std::string trajectory_residuals_csv(const MeasuredTrajectory& data, const FitResult& r);

// feature (its name, e.g. f1_hz, carries its unit), value, sigma, model and residual in that unit
// (*_in_feature_unit), residual_over_sigma, per feature.
std::string feature_residuals_csv(const MeasuredFeatures& data, const FitResult& r);

}  // namespace vi
