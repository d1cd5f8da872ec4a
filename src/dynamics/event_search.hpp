#pragma once
// Certified search for the first upward zero crossing of an ExpSignal: never steps over a root.

#include <limits>
#include <optional>

#include "dynamics/exp_signal.hpp"

namespace vi {

// Settings of the search; times in seconds within the piece.
struct CrossingSearch {
    double h_min = 0.0;    // smallest step: a crossing up and back down within h_min may be missed
    double t_tol = 0.0;    // width of the final bracket of a root
};

// The first tau in (tau0, tau_max] where f turns positive, given f(tau0) <= 0 (a value within
// roundoff of zero at tau0 counts as zero; then the sign of f' decides). From tau, the next point
// tau + h is accepted only if f + f' s + B s^2 / 2 < 0 for all s in [0, h], with B a bound of |f''|
// over the step: f cannot reach zero in between, so no crossing is stepped over.
std::optional<double> first_upcrossing(const ExpSignal& f, double tau0, double tau_max, const CrossingSearch& opt,
                                       int* evaluations = nullptr);

}  // namespace vi

namespace vi {

// Where the largest value of f over [0, tau_end] lies, to within abs_tol in value (branch and bound:
// an interval is dropped once an upper bound of f on it falls below the best value seen).
struct SignalMaximum {
    double value = 0.0;
    double tau = 0.0;
};
// `floor`: a value already reached elsewhere; parts of the interval that cannot beat it are skipped
// and, when nothing does, the result is {floor, -1}.
SignalMaximum global_maximum(const ExpSignal& f, double tau_end, double abs_tol, double h_min,
                             int* evaluations = nullptr, double floor = -std::numeric_limits<double>::infinity());

}  // namespace vi
