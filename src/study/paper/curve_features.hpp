#pragma once
// Local minima of a sampled curve y(x) with gaps, for the claims of the paper study (where does the
// rebound have its minima, where do the transients end soonest).

#include <cstddef>
#include <optional>
#include <vector>

namespace vi {

// One local minimum: position and value refined by the parabola through the lowest sample and its
// two neighbours (the sample itself when the parabola does not open upwards), the sample it was
// found at, and its prominence: how far the curve rises on its lower side before it falls below the
// minimum again (or the curve ends, or a gap comes), in the units of y.
struct CurveMinimum {
    double x = 0.0;
    double y = 0.0;
    std::size_t index = 0;
    double prominence = 0.0;
};

// Local minima of y over ascending x, in order of x. A sample without value (nullopt) is a gap: a
// minimum needs a valued neighbour on each side, so the ends of the curve and of each run of values
// are never minima. A flat bottom of equal samples counts once, at its first sample.
std::vector<CurveMinimum> local_minima(const std::vector<double>& x, const std::vector<std::optional<double>>& y);

// The minimum of `minima` closest to x0 (nullopt when there is none).
std::optional<CurveMinimum> nearest_minimum(const std::vector<CurveMinimum>& minima, double x0);

// Position of the smallest valued sample (nullopt when no sample has a value).
std::optional<std::size_t> smallest_sample(const std::vector<std::optional<double>>& y);

}  // namespace vi
