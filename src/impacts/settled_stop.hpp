#pragma once
// A stop test for a transient whose question is how its bouncing settles: the run ends at the first
// moment from which nothing the impact summary reports about the settling can change any more.

#include <functional>

#include "dynamics/transient_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "model/case.hpp"

namespace vi {

// Ends a free transient (no load acting after t = 0, every force element a Kelvin-Voigt support,
// T_p by penetration) at a moment when every contact is open and none is still compressed, once
//  - T_p and its reason are "settled" on the episodes so far and no later impact can pass the settle
//    threshold: the motion's energy E bounds every later penetration by d_eq + sqrt(2 E (K^-1)_cc),
//    since the energy of the beam and its supports about the free equilibrium never grows,
//  - the first `impacts` impacts (so T, T1, T2 of the first cycle) each have a later one of their
//    support, so that no episode can join them,
//  - the watched point's and the first contact point's extremes cannot be passed again
//    (|v - v_eq| <= sqrt(2 E (K^-1)_vv)).
// What it leaves out: the impacts after the stop (their count, later periods, a lasting contact that
// would only begin later). Returns an empty test (run to the horizon) for any other case.
std::function<bool(const RunSoFar&)> settled_stop(const Case& c, const BuiltProblem& b, int impacts = 3);

}  // namespace vi
