#pragma once
// Golden-section search: where a unimodal function of one variable is largest on an interval.

#include <functional>

namespace vi {

struct GoldenSectionPeak {
    double x = 0.0;      // where f is largest (the middle of the last bracket)
    double value = 0.0;  // f(x)
};

// The maximum of f over [a, b], f unimodal there: the bracket shrinks by the golden ratio, one new
// evaluation each time, until it is no wider than `width` (in x's own unit). At a smooth peak f is
// flat to roundoff within about sqrt(machine epsilon) of it, so x is found only to that (relative to
// the peak's curvature scale) however small the width; the value to roundoff.
GoldenSectionPeak golden_section_max(const std::function<double(double)>& f, double a, double b, double width);

}  // namespace vi
