#pragma once
// Calibration: case values estimated from a measured trajectory of the tip by bounded nonlinear
// least squares (Ceres Solver), with standard errors, 95 % intervals and correlations from the
// Jacobian at the solution (docs/calibration.md).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "io/measured_trajectory.hpp"
#include "model/case.hpp"
#include "sweep/case_paths.hpp"

namespace vi {

// One fitted value: "PATH" (start from the case's value, no bounds) or "PATH=LOW:HIGH" (SI units).
struct FitParameter {
    std::string setting;
    CasePath path;
    double start = 0.0;                 // the case's value [SI]
    std::optional<double> low, high;    // bounds [SI]
};

// Parses a --fit setting against the case. Throws InputError("--fit TEXT: reason"): an unknown or
// whole-number path, bounds reversed or not numbers, a start outside the bounds, a start of 0
// without bounds (no scale to step by).
FitParameter parse_fit_parameter(const std::string& text, const Case& c);

struct FitOptions {
    int max_iterations = 50;   // Levenberg-Marquardt iterations (--max-iterations)
};

struct FitResult {
    std::vector<double> estimate;           // [SI]
    std::vector<double> std_error;          // [SI]; NaN for an undetermined parameter
    std::vector<double> ci_low, ci_high;    // 95 %: estimate -+ 1.96 std_error
    Eigen::MatrixXd correlation;            // of the determined parameters (NaN rows for the others)
    std::vector<std::string> undetermined;  // per parameter: "" or why the data cannot fix it
    std::vector<double> model;              // the fitted model at the data's times
    std::vector<double> residual;           // model - data at each sample [data unit]
    double rms = 0.0;                       // of residual [data unit]
    double sigma = 0.0;                     // noise level used for the errors [data unit]
    bool sigma_from_residuals = true;       // estimated as rms * sqrt(N / (N - p)), else the data's sigma
    int iterations = 0, simulations = 0;
    bool converged = false;
    std::string message;                    // Ceres' reason for stopping
};

// Fits the parameters so that the case's tip trajectory (its watched point: tip_v, or tip_velocity
// for the column tip_velocity_m_s), sampled at the data's times by linear interpolation of the
// history at the case's output step, matches the data. The horizon is set to the last data time.
// Throws InputError when a trial design cannot run at the start (a bad case), std::runtime_error when
// Ceres cannot even start, StopRequested on a stop.
FitResult fit_trajectory(const Case& base, const std::vector<FitParameter>& params, const MeasuredTrajectory& data,
                         const FitOptions& o = {});

// The case's tip trajectory at `times` with the parameters set to x (what fit_trajectory fits).
std::vector<double> model_trajectory(const Case& base, const std::vector<FitParameter>& params,
                                     const std::vector<double>& x, const std::vector<double>& times,
                                     const std::string& column);

}  // namespace vi
