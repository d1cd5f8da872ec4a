#pragma once
// The figures `vibroimpact fit` draws of a trajectory or feature fit (docs/calibration.md); the
// JSON, text and tables are the library's (calibration/fit_output.hpp).

#include "calibration/least_squares.hpp"
#include "io/measured_features.hpp"
#include "io/measured_trajectory.hpp"
#include "plot/figure_gnuplot.hpp"

namespace vi::cli {

// The data and the fitted model against time, and the residual below.
FigureSpec trajectory_figure(const MeasuredTrajectory& data, const FitResult& r);
// Each feature's residual in units of its sigma.
FigureSpec feature_figure(const MeasuredFeatures& data, const FitResult& r);

}  // namespace vi::cli
