#pragma once
// What holds a contact point on its support once the actuation is gone: the beam's elastic restoring
// force there against the support's pull-off force (docs/adhesion.md §4).

#include <cstddef>

#include "fem/system.hpp"
#include "model/case.hpp"

namespace vi {

// For support k, the beam alone (no loads, no voltage, no other support), linear:
struct ContactHold {
    double point_stiffness = 0.0;  // k_p = 1 / (e^T K^-1 e) at the contact point's v [N/m]
    double held_offset = 0.0;      // how far the surface lies from the point's unloaded rest, toward it [m]
    double restoring_force = 0.0;  // k_p held_offset: how hard the beam pulls off the surface [N]
                                   // (negative: a prestressed support, the beam presses on it)
    double pull_off_force = 0.0;   // F_po of the support's adhesion [N]
    [[nodiscard]] bool sticks() const { return restoring_force < pull_off_force; }
};

// s: the case's system (build_system, a node at every support). Throws std::out_of_range when k is
// not a support, std::runtime_error when v is held there or K is singular.
ContactHold contact_hold(const System& s, const Case& c, std::size_t k);

}  // namespace vi
