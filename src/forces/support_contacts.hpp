#pragma once
// The supports' family: one contact element per [[supports]] entry on the v DOF of its node, plain
// (KelvinVoigtContact) or adhesive (AdhesiveContact) as the entry's adhesion says.

#include "forces/element_family.hpp"

namespace vi {

const ElementFamily& support_contacts();

}  // namespace vi
