#pragma once
// Certified search for the first upward zero crossing of an ExpSignal (never steps over a root), and
// the largest value of a signal over a piece by branch and bound.

#include <limits>
#include <optional>

#include "dynamics/signal/exp_signal.hpp"

namespace vi {

// Settings of the search; times in seconds within the piece.
struct CrossingSearch {
    double h_min = 0.0;    // smallest step: a crossing up and back down within h_min may be missed
    double t_tol = 0.0;    // width of the final bracket of a root
    // Evaluations left for the whole run (nullptr: unbounded). Every search charges its evaluations;
    // at zero it throws WorkLimitReached naming solver.max_steps. The stop flag and the thread's time
    // limit are checked as it goes (model/run_control.hpp).
    long* budget = nullptr;
};

// Charges n evaluations to a budget (nullptr: none) and checks the stop flag now and then; throws
// WorkLimitReached when the budget is spent.
void charge_evaluations(long* budget, long n = 1);

// A signal that is exactly zero (no terms at all: a beam at rest on a zero-gap support) never crosses.
// The first tau in (tau0, tau_max] where f turns positive, given f(tau0) <= 0 (a value within
// roundoff of zero at tau0 counts as zero; then the sign of f' decides). From tau, the next point
// tau + h is accepted only if an upper bound of f over [tau, tau + h] is negative: f cannot reach
// zero in between, so no crossing is stepped over (signal_scan.hpp: slow modes by Taylor with a
// bound of |f''|, fast ones by their amplitude, the best of every such split).
//
// The one step no bound proves is one of length h_min, forced where f is within roundoff of zero or
// grazes it more narrowly than h_min. Such steps are counted, with the largest upper bound of f over
// any of them: a crossing inside one (up and back within h_min) is not excluded, but f rose there by
// no more than that bound.
struct UnprovenSteps {
    int count = 0;
    double excess = 0.0;  // largest upper bound of f over a forced step, relative to f's size [-]
};
std::optional<double> first_upcrossing(const ExpSignal& f, double tau0, double tau_max, const CrossingSearch& opt,
                                       int* evaluations = nullptr, UnprovenSteps* unproven = nullptr);

// Where the largest value of sign * f over [0, tau_end] lies, to within max(size_tol S, rel_tol |max|)
// in value, S the signal's size (sum of its amplitudes) (branch and bound: an interval is dropped once
// an upper bound of sign * f on it falls below the best value seen plus that margin).
struct SignalMaximum {
    double value = 0.0;
    double tau = 0.0;
};
// `floor`: a value already reached elsewhere; parts of the interval that cannot beat it are skipped
// and, when nothing does, the result is {floor, -1}. sign = -1 finds the minimum of f (as -value).
SignalMaximum global_maximum(const ExpSignal& f, double tau_end, double size_tol, double rel_tol, double h_min,
                             int* evaluations = nullptr, double floor = -std::numeric_limits<double>::infinity(),
                             double sign = 1.0, long* budget = nullptr);

// Where the largest value of f over [0, tau_end] lies against a level, by the same bounds as
// global_maximum (each raised by its rounding bound) but only as far as the comparison needs:
// `below` when f <= level is proven everywhere; `above` when a value of f beyond level (1 + 2 rel_tol)
// + 2 size_tol S is seen (S the signal's size), so that global_maximum with those tolerances would
// find a maximum above the level; `undecided` otherwise (a value just above the level, or an
// interval narrower than h_min still not bounded below it). Much cheaper than global_maximum when
// the maximum lies far from the level: what a caller needs of a peak it only compares with one.
struct LevelComparison {
    enum Outcome { below, above, undecided } outcome = undecided;
    double seen = -std::numeric_limits<double>::infinity();  // the largest value evaluated
};
LevelComparison compare_with_level(const ExpSignal& f, double tau_end, double level, double size_tol, double rel_tol,
                                   double h_min, int* evaluations = nullptr, long* budget = nullptr);

}  // namespace vi
