#pragma once
// The case's electrodes as force elements on the bending DOFs (one ElectrostaticPad each).

#include <memory>
#include <vector>

#include "fem/system.hpp"
#include "forces/electrostatic_pad.hpp"
#include "model/case.hpp"

namespace vi {

// One pad per electrode of c over the system's bending DOFs; `bending_position` maps a reduced
// DOF to its index among the bending DOFs (-1 for axial). With unit_voltage, every pad is held at
// 1 V (the static continuation scales the force by V^2 itself).
std::vector<std::shared_ptr<const ElectrostaticPad>> electrode_elements(const Case& c, const System& s,
                                                                       const std::vector<int>& bending_position,
                                                                       bool unit_voltage);

}  // namespace vi
