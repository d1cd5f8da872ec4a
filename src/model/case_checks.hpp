#pragma once
// Physical and structural checks of a Case, each problem tied to the key that caused it.

#include <string>
#include <vector>

#include "model/case.hpp"
#include "model/case_problem.hpp"

namespace vi {

// Every problem found; empty when the case can be simulated. The values of every key in effect
// against the schema's ranges and the magnitude window (check_key_values), then the rules between
// keys (supports at one place, a dielectric thinner than its gap, an output step within the
// horizon, ...) and the derived scales (check_magnitudes).
std::vector<CaseProblem> check_case(const Case& c);

// True when the end conditions alone keep the beam from moving as a rigid body in bending.
bool bending_is_restrained(EndCondition left, EndCondition right);

// Euler's buckling stress of the beam's end conditions [Pa], E I beta^2 / A with beta the lowest root
// of the buckling equation (beta l = pi, 4.4934, 2 pi for pinned-pinned, clamped-pinned,
// clamped-clamped); 0 when an end is free (no axial force acts).
double buckling_stress(const Case& c);

}  // namespace vi
