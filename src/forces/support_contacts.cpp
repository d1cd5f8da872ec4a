#include "forces/support_contacts.hpp"

#include <cmath>
#include <memory>
#include <string>

#include "forces/adhesive_contact.hpp"
#include "forces/kelvin_voigt_contact.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

// Surfaces in beam coordinates (v up): below, +Support::surface (a prestress lifts it above the
// unloaded axis); above, -Support::surface. Cc from a damping ratio zeta: Cc = 2 zeta sqrt(Kc m_eff),
// with m_eff = 1 / phi1(x0)^2 the effective mass of the first unsupported bending mode (mass
// normalised) at the support: the critical damping of that mode's one-DOF model on the support spring.
class SupportContacts final : public ElementFamily {
public:
    [[nodiscard]] std::string_view name() const override { return "support contacts"; }

    [[nodiscard]] std::vector<FamilyElement> elements(const ElementSource& src) const override {
        std::vector<FamilyElement> out;
        for (std::size_t k = 0; k < src.c.supports.size(); ++k) {
            if (src.c.supports[k].linear_law()) out.push_back({contact(src, k), {"supports", k}});
        }
        return out;
    }

private:
    static double damping(const ElementSource& src, std::size_t k, const std::string& name, int dof) {
        const Support& sup = src.c.supports[k];
        if (!sup.damping_ratio) return sup.damping;
        const double phi = src.first_mode[dof];
        if (!(std::abs(phi) > 1e-9 * src.first_mode.cwiseAbs().maxCoeff())) {
            throw InputError(name + ".damping_ratio: the first mode does not move at the support (give damping)");
        }
        return 2.0 * *sup.damping_ratio * std::sqrt(sup.stiffness) / std::abs(phi);
    }

    static ForceElementPtr contact(const ElementSource& src, std::size_t k) {
        const Support& sup = src.c.supports[k];
        const SupportGeometry g = support_geometry(src, k);
        const double cc = damping(src, k, g.name, g.dof);
        if (sup.adhesion == Adhesion::none) {
            return std::make_shared<KelvinVoigtContact>(g.name, g.dof, g.sign, g.surface, sup.stiffness, cc, g.x);
        }
        // One element, not a second one beside the contact: adhesion changes when the contact opens,
        // and an element's mode is its own (docs/adhesion.md §3).
        return std::make_shared<AdhesiveContact>(g.name, g.dof, g.sign, g.surface, sup.stiffness, cc, g.x, sup.pull_off_force(),
                                                 sup.adhesion_range, sup.adhesion == Adhesion::dmt ? "DMT" : "JKR");
    }
};

}  // namespace

SupportGeometry support_geometry(const ElementSource& src, std::size_t k) {
    const Support& sup = src.c.supports[k];
    const System& s = src.system;
    SupportGeometry g;
    g.name = "supports[" + std::to_string(k) + "]";
    const int r = s.support_dof[k];
    if (r < 0) {
        throw InputError(g.name + ".position: the support sits on a node held by an end condition (v never moves there)");
    }
    g.dof = src.bending_position[static_cast<std::size_t>(r)];
    g.sign = sup.side == Side::below ? 1.0 : -1.0;
    g.surface = sup.side == Side::below ? sup.surface : -sup.surface;
    g.x = s.mesh.x[static_cast<std::size_t>(s.mesh.support_nodes[k])];
    return g;
}

const ElementFamily& support_contacts() {
    static const SupportContacts family;
    return family;
}

}  // namespace vi
