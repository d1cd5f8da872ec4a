#pragma once
// TimeFunction: the time history g(t) of a point load Q(t) = amplitude * g(t) (dimensionless).

#include <string>
#include <vector>

namespace vi {

// constant: g = 1. step: g = 0 before t_on, 1 after. harmonic: g = offset + sin(2 pi f t + phase).
// table: piecewise linear through (times, values), held constant outside the table.
struct TimeFunction {
    enum class Kind { constant, step, harmonic, table };
    Kind kind = Kind::constant;
    double t_on = 0.0;          // step time [s]
    double frequency_hz = 0.0;  // harmonic frequency [Hz]
    double phase = 0.0;         // harmonic phase [rad]
    double offset = 0.0;        // harmonic mean value [-]
    std::vector<double> times;  // table abscissae [s], strictly increasing
    std::vector<double> values; // table ordinates [-]

    // g(t).
    [[nodiscard]] double operator()(double t) const;
    // dg/dt [1/s]; at a table knot the slope after it, and 0 across a step (a jump, not a slope).
    [[nodiscard]] double slope(double t) const;
    // The largest |g(t)| over all t.
    [[nodiscard]] double max_abs() const;
    // Times in (t0, t1) where g or its slope jumps (step time, table knots), ascending.
    [[nodiscard]] std::vector<double> breakpoints(double t0, double t1) const;
};

}  // namespace vi
