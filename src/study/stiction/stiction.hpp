#pragma once
// The stiction check of a case: whether each adhesive support holds the unloaded beam down, the
// detached length of a long cantilever lying on its substrate, and the peel balance of the beam on
// each adhesive dielectric layer (docs/adhesion.md §4-5, §10).

#include <optional>
#include <string>
#include <vector>

#include "model/case.hpp"
#include "study/stiction/layer_stiction.hpp"

namespace vi {

// One adhesive support held closed with no voltage and no load.
struct SupportStiction {
    int support = 0;
    std::string law;                // "DMT" or "JKR"
    double restoring_force = 0.0;   // the beam's pull off the surface, contact point held on it [N]
    double point_stiffness = 0.0;   // k_p of the beam at the contact point [N/m]
    double held_offset = 0.0;       // the surface's distance from the point's rest, toward it [m]
    double pull_off_force = 0.0;    // F_po [N]
    bool sticks = false;            // restoring_force < pull_off_force
    // The work of adhesion at which F_po equals the restoring force: it sticks above it [J/m^2]
    // (empty when the beam presses on the support, which then holds whatever the adhesion).
    std::optional<double> critical_work_of_adhesion;
};

// The S-shaped stuck cantilever (Mastrangelo & Hsu 1993): the beam leaves the clamp at the gap h
// above the substrate and lies flat on it from x = l_d on. Energy balance of the free part (strain
// energy 6 E I h^2 / s^3 of a clamped-guided span s) against the adhesion energy gamma w per unit
// length gives l_d = (3 E t^3 h^2 / (2 gamma))^(1/4).
struct DetachedLength {
    int support = 0;              // whose gap and work of adhesion
    double gap = 0.0;             // h [m]
    double work_of_adhesion = 0.0;  // gamma [J/m^2]
    double closed_form = 0.0;     // l_d [m]
    double finite_element = 0.0;  // the same from the FE strain energy of the span (stiction_fe_length) [m]
    bool beam_longer = false;     // the case's beam is longer than l_d (it can stay stuck in the S-shape)
};

struct StictionResult {
    std::vector<SupportStiction> supports;      // the adhesive ones, in case order
    std::vector<DetachedLength> detached;       // for a cantilever (one end free) only
    std::string note;                           // why `detached` is empty with adhesive supports, or ""
    std::vector<LayerStiction> layers;          // the electrodes' adhesive layers, in case order
};

// Throws InputError when the case has neither an adhesive support nor an adhesive layer.
StictionResult stiction_check(const Case& c);

// l_d from the closed form (E the beam's effective modulus) [m].
double detached_length_closed_form(double youngs_modulus, double thickness, double gap, double work_of_adhesion);
// The same for a section of bending stiffness EI [N m^2] and width w [m]: (18 EI h^2 / (w gamma))^(1/4),
// which E w t^3 / 12 makes the line above; a beam of sections takes the section under its contact.
double detached_length_of_section(double bending_stiffness, double width, double gap, double work_of_adhesion);

// The same cantilever lying on a compliant adhesive layer, in the limit of the layer's law
// (docs/adhesion.md §9) as its range vanishes: a Winkler foundation of line stiffness k [N/m^2] that
// pulls the beam in to its rest d_0 = sqrt(2 W / k) and lets go at its face, W = w w_e [J/m]. The
// free span s is the cubic from the clamp at the gap h [m] above the face down to the face; beyond
// it the beam rests on the foundation, u = -d_0 + e^(-b x')(d_0 cos b x' + C sin b x') with
// b = (k / (4 E I))^(1/4) (EI [N m^2]); matching u and its first three derivatives at the face gives
// h / d_0 = z^2 (z + 3) / (3 (z + 1)), z = b s, solved by bisection [m]. As k grows,
// s = l_d - 1 / b + O(1 / (b^2 l_d)).
double detached_length_on_layer(double bending_stiffness, double gap, double adhesion_energy, double line_stiffness);

// l_d from the FE model of the case's beam section: the span [0, s] clamped at the gap above the
// substrate and flat on it at s (v = -h, theta = 0 there), a static solve on `elements` elements,
// its energy release rate -dU/ds = M(s)^2 / (2 E I) from the reaction moment M, and the balance
// -dU/ds = gamma w found by bisection on s (bounded) [m]; on a beam of sections EI and w are those
// at the front s (past the tip, the tip's).
double detached_length_fe(const Case& c, double gap, double work_of_adhesion, int elements);

}  // namespace vi
