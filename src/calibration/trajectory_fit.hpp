#pragma once
// Calibration: case values estimated from a measured trajectory of the watched point (the free end,
// the mid-span of a beam held at both ends) by bounded nonlinear least squares, with the record's
// time shift and calibration scale as optional nuisance parameters, from one start or several, in
// one stage or two (docs/calibration.md).

#include <string>
#include <vector>

#include "calibration/least_squares.hpp"
#include "io/measured_trajectory.hpp"
#include "model/case.hpp"

namespace vi {

// What the trajectory model holds fixed: the measurement's nuisance values where they are not
// fitted, and the least horizon (stage 1 of a two-stage fit compares the part of the record before
// the first impact with a model run over the whole record).
struct TrajectoryFixed {
    double time_shift = 0.0;  // t0 [s]: the model is read at t - t0
    double scale = 1.0;       // g: data = g * model
    double min_horizon = 0.0; // [s]
};

// The watched point's name for the case ("tip", "midspan" or "point", as history.csv names it).
// Throws InputError when the case cannot be built.
std::string watched_point_name(const Case& c);

// Throws InputError("--column NAME: ...") naming the case's columns when `column` is not
// <watched>_m or <watched>_velocity_m_s.
void check_trajectory_column(const Case& c, const std::string& column);

// The case's watched-point trajectory at `times` with the parameters set to x (case values, and
// the time shift and scale where fitted, else `fixed`'s): g * y(t - t0), y held at its t = 0 value
// before the release. y is the history at the case's output step (the data's smallest spacing when
// the case gives none), read between samples by cubic Hermite interpolation of displacement and
// velocity (displacement) or linearly (velocity). The horizon covers the latest time read.
std::vector<double> model_trajectory(const Case& base, const std::vector<FitParameter>& params,
                                     const std::vector<double>& x, const std::vector<double>& times,
                                     const std::string& column, const TrajectoryFixed& fixed = {});

// Fits the parameters so that model_trajectory matches the data: residual (model - data) / sigma_k,
// or / max |data| without a sigma column. Throws InputError when the model cannot run at the start
// (a bad case), std::runtime_error when the Jacobian at the estimate cannot be computed,
// StopRequested on a stop.
FitResult fit_trajectory(const Case& base, const std::vector<FitParameter>& params, const MeasuredTrajectory& data,
                         const FitOptions& o = {}, const TrajectoryFixed& fixed = {});

// A two-stage fit: stage 1 fits the parameters that are not contact parameters (not under
// supports[...]; the nuisance ones included) to the samples before the first impact's onset (of the
// model at the start values, shifted by the start time shift); stage 2 fits the contact parameters
// to the whole record with stage 1's values fixed; stage 2's standard errors then take in stage
// 1's uncertainty to first order (V2 + G V1 G^T, G the sensitivity of stage 2's estimate to stage 1's).
struct TwoStageFit {
    std::vector<std::size_t> stage1_params, stage2_params;  // indices into the parameters
    double split_time = 0.0;                                // the first impact's onset in data time [s]
    std::size_t split_samples = 0;                          // samples before it
    FitResult stage1, stage2;                               // stage2's errors include stage 1's, propagated
    std::vector<double> stage2_conditional_std_error;       // stage 2's with stage 1's values taken as exact
    std::vector<double> estimate;                           // every parameter, from its stage [SI]
};

// Throws InputError("--two-stage: reason") when either stage has no parameter, the model has no
// impact at the start, or fewer samples than stage 1's parameters plus one lie before it.
TwoStageFit fit_two_stage(const Case& base, const std::vector<FitParameter>& params, const MeasuredTrajectory& data,
                          const FitOptions& o = {});

}  // namespace vi
