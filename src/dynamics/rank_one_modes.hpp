#pragma once
// Decomposition of a state with one closed contact: a rank-one change of the free modal system,
// solved through its secular equation in O(n^2) instead of a dense 2n x 2n eigen solve.

#include "dynamics/state_modes.hpp"

namespace vi {

// How the left rows are formed: directly from the contact's own Kc, Cc (exact to roundoff unless
// computed roots crowd in a cluster), or from residues recomputed from the roots (Loewner; L R = I
// holds to roundoff even in clusters, at a backward error in the residues of up to 1e-8).
enum class LeftRows { direct, loewner };

// Fills s.lambda, s.paired and s.vl (sorted by |lambda|) for the contact ce closed; s.active and
// s.damping are set by the caller. False when the secular roots cannot be found or do not belong to
// this contact's equation closely enough (the caller then falls back to a dense solve).
bool rank_one_modes(const BaseModes& b, const ContactElement& ce, LeftRows left, StateModes& s);

}  // namespace vi
