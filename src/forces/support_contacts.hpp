#pragma once
// The supports' family: one contact element per [[supports]] entry of the linear law on the v DOF
// of its node, plain (KelvinVoigtContact) or adhesive (AdhesiveContact) as the entry's adhesion says.

#include <cstddef>
#include <string>

#include "forces/element_family.hpp"

namespace vi {

// Makes the contacts of supports with the linear law (Support::linear_law); a law registered by
// another family (supports[k].law) is that family's.
const ElementFamily& support_contacts();

// Where support k acts: its name ("supports[k]"), its v DOF among the bending DOFs, its side (+1
// below, -1 above), its surface's height in beam coordinates [m] and x [m]. Throws InputError when
// it sits on a node an end condition holds.
struct SupportGeometry {
    std::string name;
    int dof = -1;
    double sign = 1.0;
    double surface = 0.0;
    double x = 0.0;
};
SupportGeometry support_geometry(const ElementSource& src, std::size_t k);

}  // namespace vi
