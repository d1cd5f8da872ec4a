#pragma once
// Physical and structural checks of a Case, each problem tied to the key that caused it.

#include <string>
#include <vector>

#include "model/case.hpp"

namespace vi {

// One thing wrong with a case: the dotted key path (e.g. "supports[1].position") and what is wrong.
struct CaseProblem {
    std::string key;
    std::string message;
};

// Every problem found, in key order of the case file; empty when the case can be simulated.
std::vector<CaseProblem> check_case(const Case& c);

// True when the end conditions alone keep the beam from moving as a rigid body in bending.
bool bending_is_restrained(EndCondition left, EndCondition right);

// Euler's buckling stress of the beam's end conditions [Pa], E I beta^2 / A with beta the lowest root
// of the buckling equation (beta l = pi, 4.4934, 2 pi for pinned-pinned, clamped-pinned,
// clamped-clamped); 0 when an end is free (no axial force acts).
double buckling_stress(const Case& c);

}  // namespace vi
