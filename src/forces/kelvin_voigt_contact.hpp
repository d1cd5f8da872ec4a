#pragma once
// KelvinVoigtContact: a support as the plain unilateral Kelvin-Voigt contact (no tension), the kind the
// exact solver integrates (docs/model.md §11).

#include <string>

#include "forces/unilateral_contact.hpp"

namespace vi {

// The open contact exerts nothing; closed, the spring-damper pushes by sign F (UnilateralContact).
class KelvinVoigtContact final : public UnilateralContact {
public:
    KelvinVoigtContact(std::string name, int dof, double sign, double surface, double stiffness, double damping,
                       double x);

    [[nodiscard]] std::string kind() const override { return "Kelvin-Voigt contact"; }
    // Closed: 1/2 Kc d^2 [J]; open: 0.
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;
    [[nodiscard]] std::optional<LinearForm> linear_form() const override;
};

}  // namespace vi
