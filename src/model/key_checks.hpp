#pragma once
// The checks every key of the schema gets from its own description: a finite value, within its
// range, and (a nonzero number) within the magnitude window; a table file's rows within the window.

#include <string>
#include <vector>

#include "model/case.hpp"
#include "model/case_problem.hpp"

namespace vi {

// Appends the problems of every key in effect in every entry of c (an array's first max_entries).
void check_key_values(std::vector<CaseProblem>& out, const Case& c);

// Why a nonzero value v [SI] is outside the magnitudes double precision computes with
// (1/kMagnitudeLimit .. kMagnitudeLimit); empty when it is inside, zero or not finite.
std::string magnitude_problem(double v);

}  // namespace vi
