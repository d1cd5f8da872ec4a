#pragma once
// Certified search for the first upward zero crossing of an ExpSignal: never steps over a root.

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
