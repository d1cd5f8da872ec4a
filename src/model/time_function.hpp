#pragma once
// TimeFunction: the time history g(t) of a point load Q(t) = amplitude * g(t) (dimensionless).

#include <string>
#include <vector>

namespace vi {

// Largest departure of a table from the straight line between two integration stops, as a fraction
// of its largest |g|: knots that stay within it are integrated through by CVODE's error control
// instead of each ending a step (a sampled signal's rows are not corners to resolve one by one; a
// stop and restart at each of 1e4 rows cost 7 steps and 5 factorisations each).
inline constexpr double kTableStopTolerance = 1e-6;
// The same for the exact solver's pieces, which take g as straight between their ends: rows on one
// straight line to roundoff (a constant or a linear stretch written row by row) are one piece.
inline constexpr double kTableExactTolerance = 1e-14;

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
    // Times in (t0, t1) where g or its slope jumps, ascending: the ends of the pieces of a solver that
    // takes g as straight between them (the step time; a table's first and last knots and its knots
    // where it leaves the straight line from the previous one kept by more than kTableExactTolerance
    // of its largest |g|). O(rows).
    [[nodiscard]] std::vector<double> breakpoints(double t0, double t1) const;
    // Times in (t0, t1) where an integrator with error control must stop, ascending: the step time,
    // a table's first and last knots, and its knots where it leaves the straight line from the
    // previous stop by more than kTableStopTolerance of its largest |g|. O(rows).
    [[nodiscard]] std::vector<double> stops(double t0, double t1) const;
};

}  // namespace vi
