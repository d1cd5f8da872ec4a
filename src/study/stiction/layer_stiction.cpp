#include "study/stiction/layer_stiction.hpp"

#include <cmath>

#include "problem/beam_model.hpp"
#include "statics/static_minimum.hpp"
#include "forces/adhesive_layer_law.hpp"
#include "statics/layer_hold.hpp"
#include "study/stiction/stiction.hpp"

namespace vi {

std::vector<LayerStiction> layer_stiction(const Case& c) {
    std::vector<LayerStiction> out;
    bool any = false;
    for (const Electrode& e : c.electrodes) any = any || (e.work_of_adhesion && e.dielectric_thickness > 0.0);
    if (!any) return out;
    const BeamModel b = build_beam_model(c);
    const bool cantilever = (c.beam.left == EndCondition::free) != (c.beam.right == EndCondition::free);
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        const Electrode& e = c.electrodes[k];
        if (!e.work_of_adhesion || !(e.dielectric_thickness > 0.0)) continue;
        LayerStiction s;
        s.hold = layer_hold(c, k);
        const SectionResultants under = electrode_section(c, k);
        const double EI = under.EI;
        const double contact_width = layer_contact_width(c, k);
        const double stiffness = e.dielectric_modulus * contact_width / e.dielectric_thickness;
        const AdhesiveLayerLaw law(stiffness, s.hold.adhesion_energy, e.adhesion_range);
        // Laid at the law's rest on the face, toward the electrode.
        const double sign = e.side == Side::above ? 1.0 : -1.0;
        const Eigen::VectorXd start = held_flat(b.system, b.K, s.hold.span_from, s.hold.span_to,
                                                sign * (s.hold.air_gap + law.rest_penetration()));
        const StaticState settled = minimize_static_energy(b.K, b.forces,
                                                           Eigen::VectorXd::Zero(start.size()), start,
                                                           c.solver.max_static_iterations);
        if (const auto touch = layer_contact(c, k, b.system, settled.q)) {
            s.settled_stuck = true;
            s.settled_from = touch->first;
            s.settled_to = touch->second;
        }
        if (cantilever) {
            s.detached_closed_form = c.beam.sections.empty()
                                         ? detached_length_closed_form(c.material.effective_modulus(), c.beam.thickness,
                                                                       s.hold.air_gap, *e.work_of_adhesion)
                                         : detached_length_of_section(EI, contact_width, s.hold.air_gap, *e.work_of_adhesion);
            s.detached_on_layer = detached_length_on_layer(EI, s.hold.air_gap, s.hold.adhesion_energy, stiffness);
            if (s.settled_stuck) {
                s.detached_settled = c.beam.right == EndCondition::free ? s.settled_from : c.beam.length - s.settled_to;
            }
        }
        out.push_back(s);
    }
    return out;
}

}  // namespace vi
