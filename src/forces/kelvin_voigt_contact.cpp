#include "forces/kelvin_voigt_contact.hpp"

namespace vi {

KelvinVoigtContact::KelvinVoigtContact(std::string name, int dof, double sign, double surface, double stiffness,
                                       double damping, double x)
    : UnilateralContact(std::move(name), dof, sign, surface, stiffness, damping, x, 0.0) {}

double KelvinVoigtContact::stored_energy(const ElementState& s, int mode) const {
    if (mode != 1) return 0.0;
    const double d = penetration(s);
    return 0.5 * stiffness_ * d * d;
}

std::optional<LinearForm> KelvinVoigtContact::linear_form() const {
    return LinearForm{UnilateralSpringDamper{dofs_[0], sign_, surface_, stiffness_, damping_}};
}

}  // namespace vi
