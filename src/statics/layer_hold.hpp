#pragma once
// What holds a beam down on an adhesive dielectric layer once the voltage is gone: a beam lying on
// a surface lets go by peeling from the edges of its contact, where the strain energy it releases
// per unit length, M^2 / (2 E I), must exceed the adhesion energy w w_e (docs/adhesion.md §10).

#include <Eigen/Dense>
#include <cstddef>
#include <optional>
#include <vector>

#include "fem/system.hpp"
#include "fem/section_properties.hpp"
#include "model/case.hpp"

namespace vi {

// The part of length s of the case's beam from its left end (from_left) or its right end (its
// sections, mirrored from the right, the last one carried on past the far end; its material; no
// supports, loads, electrodes, residual stress or stretching) with end condition `end` at that end,
// held at v = -offset, theta = 0 at distance s (flat on the surface from there on), on `elements`
// elements and a node at each section end: the reaction moment M and shear V at the front [N m, N]
// and the release rate M^2 / (2 EI) [J/m], EI the section's at the front (the J-integral of a peeled
// beam: moving the front by ds releases that strain energy). `end` must not be free.
struct PeelRate {
    double release_rate = 0.0;
    double moment = 0.0;
    double shear = 0.0;
};
PeelRate peel_release_rate(const Case& c, EndCondition end, double s, double offset, int elements, bool from_left = true);

// The section under the middle of electrodes[k] of c (the width its force and layer take when it
// gives none, the EI that holds the beam flat on it).
SectionResultants electrode_section(const Case& c, std::size_t k);

// The width of electrodes[k]'s layer that the beam touches [m]: the electrode's (or the section's)
// width times the solid fraction its release holes leave.
double layer_contact_width(const Case& c, std::size_t k);

// The sections of the part of length s [m] of beam b from its left end (or its right end, mirrored)
// as x/s; none for a beam without sections.
std::vector<BeamSection> part_sections(const Beam& b, double s, bool from_left);

// The peel balance of the beam on electrode k's adhesive layer, rigid and of zero range (the limit of
// the law as both vanish), with no voltage, no other electrode and no support.
struct LayerHold {
    std::size_t electrode = 0;
    double air_gap = 0.0;          // h = gap - t_d: the layer's face from the beam's rest [m]
    double adhesion_energy = 0.0;  // W = w w_e, w_e the contact width [J/m]
    double holding_moment = 0.0;   // sqrt(2 E I W): the edge moment at which the beam peels [N m]
    double span_from = 0.0, span_to = 0.0;  // the layer's span [m]
    // Held flat on the layer over its whole span, the release rate at each end of the span [J/m]
    // (0 beside a free overhang, which stays flat; +inf where the span starts at a held end).
    double release_from = 0.0, release_to = 0.0;
    // Peeled until each edge releases no more than W: the contact left [m], if any.
    bool sticks = false;
    double contact_from = 0.0, contact_to = 0.0;
    // The beam's pull off the layer over that contact (over the whole span when none is left): the
    // sum of the shear forces at its edges [N], and the adhesion's pull if the same contact were lifted
    // evenly, q_max (contact_to - contact_from) [N] (0 when none is left).
    double restoring_force = 0.0;
    double even_pull_off_force = 0.0;
    double critical_work_of_adhesion = 0.0;  // w above which some contact stays [J/m^2]
};
// Throws std::invalid_argument when electrode k has no adhesive layer.
LayerHold layer_hold(const Case& c, std::size_t k);

// Bending displacements (the order of s.bending) of the beam held flat at v = height, theta = 0 at
// every node in [from, to] [m] and elsewhere in equilibrium under K_b (the bending stiffness) alone.
Eigen::VectorXd held_flat(const System& s, const SparseMatrix& K_b, double from, double to, double height);

// Where the beam (bending displacements q) touches electrode k's layer, that is where the
// penetration sign v(x) - (gap - t_d) is >= 0: the first and last such x in the span [m], from the
// Hermite interpolation of each element (sampled, then bisected to rounding); empty when nowhere.
std::optional<std::pair<double, double>> layer_contact(const Case& c, std::size_t k, const System& s,
                                                       const Eigen::VectorXd& q);

}  // namespace vi
