#include "fem/section_properties.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace vi {
namespace {

const LayerMaterial& material_named(const Case& c, const std::string& name) {
    for (const LayerMaterial& m : c.materials) {
        if (m.name == name) return m;
    }
    throw std::invalid_argument("no material named \"" + name + "\"");
}

double bending_modulus(const Case& c, const LayerMaterial& m) {
    const double nu = m.poisson_ratio;
    return c.material.plate_modulus ? m.youngs_modulus / (1.0 - nu * nu) : m.youngs_modulus;
}

// The layered section: transformed to the reference modulus, then scaled back (classical laminated
// beam; e.g. S. Timoshenko and J. Gere, Mechanics of Materials, the transformed-section method).
void add_layers(const Case& c, const BeamSection& s, double w, SectionResultants& r) {
    double ea = 0.0, first = 0.0, z = 0.0;
    for (const Layer& l : s.layers) {
        const double e = bending_modulus(c, material_named(c, l.material));
        ea += e * w * l.thickness;
        first += e * w * l.thickness * (z + 0.5 * l.thickness);
        z += l.thickness;
    }
    r.thickness = z;
    r.EA = ea;
    r.neutral_axis = first / ea;
    z = 0.0;
    for (const Layer& l : s.layers) {
        const LayerMaterial& m = material_named(c, l.material);
        const double e = bending_modulus(c, m), t = l.thickness, a = w * t;
        const double arm = z + 0.5 * t - r.neutral_axis;
        r.EI += e * (w * t * t * t / 12.0 + a * arm * arm);
        r.rho_A += m.density * a;
        r.stress_force += m.residual_stress * a;
        // A linear stress sigma_r + Gamma (z - z_k) over the layer: its force at the layer's middle,
        // and the gradient's own moment Gamma w t^3 / 12.
        r.stress_moment += m.residual_stress * a * arm + m.stress_gradient * w * t * t * t / 12.0;
        z += t;
    }
}

}  // namespace

SectionFactors hole_factors(const Holes& h) {
    const double r = h.size / h.pitch;
    const double open = h.shape == HoleShape::circle ? 0.25 * std::numbers::pi * r * r : r * r;
    return {1.0 - r, 1.0 - open, 1.0 - open};
}

SectionFactors section_factors(const Beam& beam, std::size_t k) {
    const std::optional<Holes>& h = beam.sections.at(k).holes;
    return h ? hole_factors(*h) : SectionFactors{};
}

SectionResultants plain_section(const Case& c) {
    const Beam& b = c.beam;
    SectionResultants r;
    r.width = b.width;
    r.thickness = b.thickness;
    r.EA = c.material.effective_modulus() * b.area();
    r.EI = c.material.effective_modulus() * b.second_moment();
    r.rho_A = c.material.density * b.area();
    r.neutral_axis = 0.5 * b.thickness;
    r.stress_force = b.residual_stress * b.area();
    return r;
}

SectionResultants section_resultants(const Case& c, std::size_t k) {
    const BeamSection& s = c.beam.sections.at(k);
    SectionResultants r;
    r.width = s.width.value_or(c.beam.width);
    if (s.layers.empty()) {
        r.thickness = s.thickness.value_or(c.beam.thickness);
        const double a = r.width * r.thickness, e = c.material.effective_modulus();
        r.EA = e * a;
        r.EI = e * (r.width * r.thickness * r.thickness * r.thickness / 12.0);
        r.rho_A = c.material.density * a;
        r.neutral_axis = 0.5 * r.thickness;
        r.stress_force = c.beam.residual_stress * a;
    } else {
        add_layers(c, s, r.width, r);
    }
    // The holes leave the neutral axis where it is (they go through the whole stack); the layers'
    // residual stresses act as eigenstrains of the material, so their resultants follow EA and EI.
    if (s.holes) {
        const SectionFactors f = section_factors(c.beam, k);
        r.EA *= f.stiffness;
        r.EI *= f.stiffness;
        r.stress_force *= f.stiffness;
        r.stress_moment *= f.stiffness;
        r.rho_A *= f.mass;
        r.solid_fraction = f.area;
        r.holes = s.holes;
    }
    return r;
}

std::vector<SectionResultants> beam_sections(const Case& c) {
    if (c.beam.sections.empty()) return {plain_section(c)};
    std::vector<SectionResultants> out;
    for (std::size_t k = 0; k < c.beam.sections.size(); ++k) out.push_back(section_resultants(c, k));
    return out;
}

std::size_t section_index_at(const Beam& beam, double s) {
    std::size_t k = 0;
    while (k + 1 < beam.sections.size() && s >= beam.sections[k + 1].from) ++k;
    return k;
}

ElementProperties element_properties(const Case& c, const SectionResultants& s, bool layered) {
    const double e = c.material.effective_modulus();
    if (!layered) {
        // The same expressions as the plain beam's, so that a section repeating it is bit-for-bit it.
        const double a = s.width * s.thickness;
        const double i = s.width * s.thickness * s.thickness * s.thickness / 12.0;
        // rho is rho A over the element's A (holes put different factors on the two; 1 when solid).
        const double area_factor = s.EA / (e * a);
        return {e, a * area_factor, i * (s.EI / (e * i)),
                c.material.density * ((s.rho_A / (c.material.density * a))) / area_factor};
    }
    const double a = s.EA / e;
    return {e, a, s.EI / e, s.rho_A / a};
}

double held_axial_force(const Case& c, const std::vector<SectionResultants>& sections) {
    if (!c.beam.axis_held()) return 0.0;
    if (c.beam.sections.empty()) return sections.front().stress_force;
    double strain_sum = 0.0, compliance = 0.0;
    for (std::size_t k = 0; k < sections.size(); ++k) {
        const double len = c.beam.sections[k].to - c.beam.sections[k].from;
        strain_sum += sections[k].stress_force * len / sections[k].EA;
        compliance += len / sections[k].EA;
    }
    return strain_sum / compliance;
}

}  // namespace vi
