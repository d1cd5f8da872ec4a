#pragma once
// The registry of element families: every kind of force element a case can describe, in the order
// build_beam_model adds their elements (the order of the force set, which fixes the order of every
// sum over elements, so it is kept as it is).

#include <vector>

#include "forces/element_family.hpp"

namespace vi {

const std::vector<const ElementFamily*>& element_families();

}  // namespace vi
