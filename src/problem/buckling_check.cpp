#include "problem/buckling_check.hpp"

#include <exception>
#include <string>

#include "fem/buckling.hpp"
#include "fem/system.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

// The key the compression comes from (see the header).
std::string compression_key(const Case& c) {
    bool plain = false;
    for (const BeamSection& s : c.beam.sections) plain = plain || s.layers.empty();
    if (plain && c.beam.residual_stress < 0.0) return "beam.residual_stress";
    std::size_t worst = c.materials.size();
    for (std::size_t i = 0; i < c.materials.size(); ++i) {
        bool used = false;
        for (const BeamSection& s : c.beam.sections) {
            for (const Layer& l : s.layers) used = used || l.material == c.materials[i].name;
        }
        if (used && (worst == c.materials.size() || c.materials[i].residual_stress < c.materials[worst].residual_stress)) {
            worst = i;
        }
    }
    if (worst == c.materials.size()) return "beam.residual_stress";
    return "materials[" + std::to_string(worst) + "].residual_stress";
}

}  // namespace

void check_sectioned_buckling(std::vector<CaseProblem>& out, const Case& c) {
    if (c.beam.sections.empty() || !c.beam.axis_held()) return;
    System s;
    double critical = 0.0;
    try {
        s = build_system(c, SupportModel::none);
        if (!(s.axial_force < 0.0)) return;
        critical = buckling_force(s);
    } catch (const std::exception&) {
        return;  // sections or a stiffness the other checks refuse, each with its own message
    }
    if (-s.axial_force < critical) return;
    out.push_back({compression_key(c),
                   "the sections' residual stresses compress the beam held at both ends by " +
                       significant(-s.axial_force, 4) + " N, at or beyond its buckling force " + significant(critical, 4) +
                       " N (the Euler load of the sectioned beam, " + significant(-s.axial_force / critical, 3) +
                       " times it): the straight beam buckles, which the small-deflection model does not follow; "
                       "less compression, a stiffer section or a shorter beam is needed"});
}

}  // namespace vi
