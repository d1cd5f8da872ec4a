#pragma once
// Decomposition of a state with one closed contact: a rank-one change of the free modal system,
// solved through its secular equation in O(n^2) instead of a dense 2n x 2n eigen solve.

#include "dynamics/state_modes.hpp"

namespace vi {

// Fills s.lambda, s.paired and s.vl (sorted by |lambda|) for the contact ce closed; s.active and
// s.damping are set by the caller. False when the secular roots cannot be found or do not belong to
// this contact's equation closely enough (the caller then falls back to a dense solve).
bool rank_one_modes(const BaseModes& b, const ContactElement& ce, StateModes& s);

}  // namespace vi
