#pragma once
// Bounded nonlinear least squares over scaled parameters (Ceres Solver's Levenberg-Marquardt with
// central differences), from one start or several on threads, and the uncertainty of the solution
// from the Jacobian there: what the trajectory and feature fits share (docs/calibration.md).

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "calibration/fit_parameter.hpp"

namespace vi {

// The weighted residuals r (residuals values) at the parameters x [SI]. Throws std::exception when
// the model cannot be computed at x (a failed step for the solver), StopRequested on a stop.
using ResidualFunction = std::function<void(const std::vector<double>& x, double* r)>;

struct LeastSquaresProblem {
    std::vector<FitParameter> params;
    int residuals = 0;
    ResidualFunction evaluate;
    // The residuals are (model - data) / sigma with the data's own sigma: the covariance is
    // (J^T J)^-1. Otherwise the noise is estimated from them: s^2 (J^T J)^-1, s^2 = SSR / (N - p).
    bool sigma_known = false;
};

struct FitOptions {
    int max_iterations = 50;   // Levenberg-Marquardt iterations per start (--max-iterations)
    int starts = 1;            // starting points (--starts): the case's values first
    int threads = 0;           // threads for the starts (--threads); 0: the CPUs the process may use
    // Sees the work as it goes, in iterations of the budget starts x max_iterations: (1, 0) after
    // each iteration of a start, and (0, the rest of its share) when a start ends sooner. Called from
    // the starts' threads, possibly at once.
    std::function<void(int iterations, int unused)> progress;
};

// One local solve from one start.
struct StartRun {
    std::vector<double> start, end;   // [SI]
    double cost = 0.0;                // 1/2 sum r^2 at the end (infinite when the start cannot run)
    bool converged = false;
    std::string message;              // Ceres' reason for stopping
    int iterations = 0, simulations = 0;
    int minimum = -1;                 // which distinct minimum (0: the best's), -1 when not converged
};

// What a fit reports (the trajectory and feature fits fill model, residual and the noise).
struct FitResult {
    std::vector<double> estimate;           // [SI]
    std::vector<double> std_error;          // [SI]; NaN for an undetermined parameter
    std::vector<double> ci_low, ci_high;    // 95 %: estimate -+ 1.96 std_error
    Eigen::MatrixXd correlation;            // of the determined parameters (NaN rows for the others)
    std::vector<std::string> undetermined;  // per parameter: "" or why the data cannot fix it
    std::vector<double> model;              // the fitted model at the data (samples or features)
    std::vector<double> residual;           // model - data [data unit]
    double rms = 0.0;                       // of residual [data unit]
    double sigma = 0.0;                     // noise level estimated from the residuals [data unit]
    bool sigma_from_residuals = true;       // else the data's own sigma
    double cost = 0.0;                      // 1/2 sum of the weighted residuals squared at the estimate
    int iterations = 0;                     // of the best start
    int simulations = 0;                    // over every start and the Jacobian at the estimate
    bool converged = false;                 // the best start converged
    std::string message;                    // Ceres' reason for stopping (best start)
    std::vector<StartRun> starts;           // every start, in order (the first is the case's values)
    std::size_t best = 0;                   // index of the best start
    int distinct_minima = 0;                // among the converged starts
};

// The starting points of `count` starts: the parameters' starts first, then points of a Halton
// sequence within the bounds (in log space when LOW > 0 and HIGH / LOW >= 100), and start * 2^(2u-1)
// (u in [0, 1)) for a parameter without bounds. Deterministic.
std::vector<std::vector<double>> start_points(const std::vector<FitParameter>& params, int count);

// Fits p from o.starts starting points on o.threads threads and reports the best (lowest cost; the
// first such start on a tie) with its uncertainty. The result does not depend on the thread count.
// Throws StopRequested on a stop, std::runtime_error when the Jacobian at the estimate cannot be
// computed. The case's start must run (the caller checks it; a failed start is reported, not thrown).
FitResult fit_least_squares(const LeastSquaresProblem& p, const FitOptions& o);

// The Jacobian d r / d x of p's residuals at x [residual unit / SI] by central differences; adds the
// model runs to `calls`. Throws std::runtime_error when a difference step cannot run.
Eigen::MatrixXd jacobian_at(const LeastSquaresProblem& p, const std::vector<double>& x, int& calls);

// The index of the weighted residual (model - data) / sigma with the largest magnitude when their
// sum of squares is not a finite number (the misfit overflows double precision, or a residual is
// not finite), else weighted.size(). A fit checks its start with it before Ceres sees the problem.
std::size_t overflowing_residual(const std::vector<double>& weighted);

// The covariance of r's estimate [SI^2] from its standard errors and correlations (NaN for the
// undetermined parameters), and back: set_covariance replaces the standard errors, intervals and
// correlations of r's determined parameters by those of v.
Eigen::MatrixXd covariance(const FitResult& r);
void set_covariance(FitResult& r, const Eigen::MatrixXd& v);

}  // namespace vi
