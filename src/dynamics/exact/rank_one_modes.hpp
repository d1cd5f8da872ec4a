#pragma once
// Decomposition of a state with one closed contact: a rank-one change of the free modal system,
// solved through its secular equation in O(n^2) instead of a dense 2n x 2n eigen solve.

#include <vector>

#include "dynamics/exact/secular.hpp"
#include "dynamics/exact/state_modes.hpp"

namespace vi {

// How the left rows are formed: directly from the contact's own Kc, Cc (exact to roundoff unless
// computed roots crowd in a cluster), or from residues recomputed from the roots (Loewner; L R = I
// holds to roundoff even in clusters, at a backward error in the residues of up to 1e-8).
enum class LeftRows { direct, loewner };

// The eigenvalues of the state with one contact closed, and what both ways of forming the vectors
// need: the secular equation is solved once however many ways the vectors are then formed.
struct RankOneRoots {
    struct Candidate {
        cd z;
        bool paired;
        int free_mode;  // -1 for a root of the secular equation; else the uncoupled mode it stays
        cd partner;     // the other pole of that mode [1/s]
    };
    std::vector<Candidate> cand;      // every representative eigenvalue [1/s], unsorted
    std::vector<SecularMode> modes;   // the coupled modes
    std::vector<int> coupled;         // their indices in the base modes
    std::vector<cd> pall;             // their poles, two per coupled mode [1/s]
    std::vector<cd> rho_hat;          // the residues at pall recomputed from the roots (Loewner)
};

// Solves the secular equation of contact ce on the free modes. False when the roots cannot be found
// or do not belong to this contact's equation closely enough (the caller then falls back to a dense
// solve).
bool rank_one_roots(const BaseModes& b, const ContactElement& ce, RankOneRoots& r);

// Fills s.lambda, s.paired and s.vl (sorted by |lambda|) from the roots; s.active and s.damping are
// set by the caller. False when a normalisation vanishes or overflows.
bool rank_one_modes(const BaseModes& b, const ContactElement& ce, const RankOneRoots& roots, LeftRows left,
                    StateModes& s);

}  // namespace vi
