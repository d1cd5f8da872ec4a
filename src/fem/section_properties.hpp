#pragma once
// Cross-section properties of a beam of sections and layers (SI): the transformed (laminated)
// section's neutral axis, EA, EI and rho A, and the resultants of its layers' residual stresses.

#include <optional>
#include <vector>

#include "fem/beam_element.hpp"
#include "model/case.hpp"

namespace vi {

// Factors a section's release holes put on its solid properties (1 for a solid section).
struct SectionFactors {
    double stiffness = 1.0;  // on EA, EI and the residual stresses' force and moment [-]
    double mass = 1.0;       // on rho A [-]
    double area = 1.0;       // on the plan area an electrode faces [-]
};

// The factors of holes of size s at pitch p (r = s / p < 1) in a square array (docs/model.md,
// perforated sections): stiffness mu = 1 - r, the ligament efficiency; mass and area the solid
// fraction, 1 - r^2 for square holes, 1 - (pi / 4) r^2 for round ones.
SectionFactors hole_factors(const Holes& h);

// One section's properties, each over the whole width.
struct SectionResultants {
    double width = 0.0;          // w [m]
    double thickness = 0.0;      // t, the stack's total [m]
    double EA = 0.0;             // axial stiffness [N]
    double EI = 0.0;             // bending stiffness about the neutral axis [N m^2]
    double rho_A = 0.0;          // mass per length [kg/m]
    double neutral_axis = 0.0;   // its height above the bottom face [m]
    // The layers' residual stresses while the beam is held straight and at length: their axial force
    // (tension positive) [N] and their moment about the neutral axis (tension on top positive) [N m].
    // Released, the section takes the strain -N_r / EA and the curvature M_r / EI (curling up).
    double stress_force = 0.0;
    double stress_moment = 0.0;
    double solid_fraction = 1.0;  // of the plan area, what the holes leave [-]
    std::optional<Holes> holes;   // the section's release holes; unset: solid
};

// The factors of section k of the beam (its holes', or 1).
SectionFactors section_factors(const Beam& beam, std::size_t k);

// The plain beam's section ([beam] width and thickness of [material]; beam.residual_stress as its
// stress force, no moment).
SectionResultants plain_section(const Case& c);

// Section k of c.beam.sections: its width and thickness, or its layers by the transformed section
// (moduli E_k, or E_k / (1 - nu_k^2) with material.plate_modulus) about the neutral axis
// z_n = sum E_k t_k z_k / sum E_k t_k. Throws std::invalid_argument for a layer naming no material
// (check_case reports it first).
SectionResultants section_resultants(const Case& c, std::size_t k);

// Every section of c, in order; the plain section alone for a beam without sections.
std::vector<SectionResultants> beam_sections(const Case& c);

// The index into beam_sections(c) of the section holding x/l = s (the later one at a boundary).
std::size_t section_index_at(const Beam& beam, double s);

// The element properties of a section: E the plain material's modulus and A, I, rho such that
// E A, E I and rho A are the section's (for an unlayered section exactly w t, w t^3 / 12, rho).
ElementProperties element_properties(const Case& c, const SectionResultants& s, bool layered);

// The axial force of a beam whose ends hold its axis, from the sections' stress forces N_i: the
// ends keep its length, so N = sum (N_i L_i / EA_i) / sum (L_i / EA_i) (uniform: N_i) [N]; 0 when an
// end is free.
double held_axial_force(const Case& c, const std::vector<SectionResultants>& sections);

}  // namespace vi
