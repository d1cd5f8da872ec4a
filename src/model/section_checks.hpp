#pragma once
// The rules of a beam's sections and layers that no single key's range states: the sections cover
// the beam in order without gaps or overlaps, every layer names a material, material names differ.

#include <string>
#include <vector>

#include "model/case.hpp"
#include "model/case_problem.hpp"

namespace vi {

// Why holes of `size` at `pitch` [m] (both positive) cannot be: empty when size < pitch.
std::string holes_pitch_problem(double size, double pitch);

// Appends the problems of c.beam.sections and c.materials, each naming its key.
void check_sections(std::vector<CaseProblem>& out, const Case& c);

}  // namespace vi
