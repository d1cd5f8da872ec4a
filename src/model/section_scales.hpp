#pragma once
// The bending stiffness and mass per length of each part of a beam from the case alone (SI), for
// the estimates made before a model is built (run size, time scales, magnitudes).

#include <vector>

#include "model/case.hpp"

namespace vi {

// One part of the beam: its share of the length and its section's scales.
struct SectionScale {
    double fraction = 0.0;  // (to - from) of the part [-]
    double EI = 0.0;        // bending stiffness about its neutral axis [N m^2]
    double rho_A = 0.0;     // mass per length [kg/m]
};

// The plain beam as one part (E w t^3 / 12, rho w t), or each of c.beam.sections: its width and
// thickness of [material], or its layers by the transformed section about their neutral axis (the
// same values as the finite-element model's, fem/section_properties.hpp; a layer naming no material
// counts as absent: check_case reports it).
std::vector<SectionScale> section_scales(const Case& c);

// Effective values of a beam of parts for the closed-form estimates [N m^2, kg/m]: the mean mass per
// length m / l, and the EI that gives the uniform beam of that mass the first frequency of Rayleigh's
// method with the static deflection under a uniform load (Lord Rayleigh, *The Theory of Sound*, 1877;
// the beam's own deflection, in ratio to the uniform beam's in its own, so that a uniform beam gives
// back its own EI); the parts' EI in series when the ends do not hold the beam; for the plain beam
// its own E I and rho A.
struct EffectiveBeam {
    double EI = 0.0;
    double rho_A = 0.0;
    double wave_max = 0.0;  // the largest sqrt(EI_i / rho_A_i) of the parts [m^2/s]
};
EffectiveBeam effective_beam(const Case& c);

}  // namespace vi
