#pragma once
// The buckling rule of a beam of sections whose ends hold its axis: its residual and layer stresses'
// axial force must stay a tension or a compression below the sections' own Euler buckling force.

#include <vector>

#include "model/case.hpp"
#include "model/case_checks.hpp"

namespace vi {

// Appends the problem of c when its beam has [[beam.sections]], both ends hold the axis, and the
// held axial force N (fem/section_properties.hpp, held_axial_force) is a compression at or beyond
// the finite-element buckling force (fem/buckling.hpp). It names beam.residual_stress when an
// unlayered section carries that stress in compression, else the residual_stress of the most
// compressed material in the layers.
void check_sectioned_buckling(std::vector<CaseProblem>& out, const Case& c);

}  // namespace vi
