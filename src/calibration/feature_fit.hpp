#pragma once
// Calibration from measured features (first natural frequency, quality factor, period of free
// impact vibrations, rebound, peak force, closing time, pull-in voltage): the same least squares as
// the trajectory fit, one residual (model - value) / sigma per feature (docs/calibration.md).

#include <stdexcept>
#include <string>
#include <vector>

#include "calibration/least_squares.hpp"
#include "io/measured_features.hpp"
#include "model/case.hpp"

namespace vi {

// The model gives no value for a feature at a design (no second impact for T_s, no pull-in before
// touch-down for V_PI_V): a failed step while fitting.
class FeatureMissing : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws InputError("FILE:LINE: NAME: reason") for a feature the case cannot have: V_PI_V or
// closing_time_s without an electrode.
void check_features(const Case& c, const MeasuredFeatures& data);

// The model's value of each feature of `data` (in its order) with the parameters set to x:
// f1_hz and q1 from the transient model's build (the first bending mode of the beam without its
// supports; Q1 = 1 / (2 zeta_1), zeta_1 the Rayleigh damping ratio at that frequency), the
// impact features from a transient run as a sweep point computes them (the sweep columns of the same
// names), V_PI_V from the pull-in analysis. Throws FeatureMissing naming the feature, InputError
// when a case check refuses the design, std::runtime_error on numerical trouble.
std::vector<double> model_features(const Case& base, const std::vector<FitParameter>& params,
                                   const std::vector<double>& x, const MeasuredFeatures& data);

// Fits the parameters (case values only) to the features. Throws InputError when the model cannot
// compute a feature at the start (naming it and its line), as fit_trajectory otherwise.
FitResult fit_features(const Case& base, const std::vector<FitParameter>& params, const MeasuredFeatures& data,
                       const FitOptions& o = {});

}  // namespace vi
