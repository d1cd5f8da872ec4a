#pragma once
// The case's electrodes as force elements on the bending DOFs (one ElectrostaticPad each).

#include <memory>
#include <vector>

#include "fem/system.hpp"
#include "forces/dielectric_contact.hpp"
#include "forces/electrostatic_pad.hpp"
#include "model/case.hpp"

namespace vi {

// Gauss points (`per_piece` on every element's overlap with the span) over the span [from, to] [m]
// of the beam, and the bending DOFs they touch (point indices refer to `dofs`); `bending_position`
// as below.
struct SpanQuadrature {
    std::vector<int> dofs;
    std::vector<PadPoint> points;
};
SpanQuadrature span_quadrature(const System& s, const std::vector<int>& bending_position, double from, double to,
                               int per_piece = kPadGaussPoints);

// One pad per electrode of c over the system's bending DOFs; `bending_position` maps a reduced
// DOF to its index among the bending DOFs (-1 for axial). With unit_voltage, every pad is held at
// 1 V (the static continuation scales the force by V^2 itself).
std::vector<std::shared_ptr<const ElectrostaticPad>> electrode_elements(const Case& c, const System& s,
                                                                       const std::vector<int>& bending_position,
                                                                       bool unit_voltage);

// One distributed contact per electrode with a dielectric layer (dielectric_thickness > 0): the
// beam landing on the layer; named "electrodes[i].dielectric". An electrode without a layer has none
// (the beam must not reach its face: docs/electrostatics.md §2).
std::vector<std::shared_ptr<const DielectricContact>> dielectric_contacts(const Case& c, const System& s,
                                                                          const std::vector<int>& bending_position);

}  // namespace vi
