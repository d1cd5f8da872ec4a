#pragma once
// KelvinVoigtContact: a support (motion limiter) as a unilateral Kelvin-Voigt spring-damper on the
// transverse DOF of its node (DESIGN.md §2; docs/model.md §11).

#include <string>
#include <vector>

#include "forces/force_element.hpp"

namespace vi {

// Surface at height `surface` [m] on side `sign` (+1 below the beam, -1 above), stiffness Kc [N/m]
// and damping Cc [N s/m]. Penetration d = sign (surface - v), force magnitude F = Kc d + Cc dd/dt,
// force on the DOF sign F. Mode 0: open (no force); mode 1: closed. It closes when d > 0 and F > 0
// both hold and opens when F falls through 0 (no tension: a damped contact opens while d > 0).
class KelvinVoigtContact final : public ForceElement {
public:
    KelvinVoigtContact(std::string name, int dof, double sign, double surface, double stiffness, double damping,
                       double x);

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override { return "Kelvin-Voigt contact"; }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }
    [[nodiscard]] int modes() const override { return 2; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const override;
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;
    [[nodiscard]] double dissipated_power(const ElementState& s, int mode) const override;
    [[nodiscard]] double input_power(const ElementState&, int) const override { return 0.0; }

    // Open: min(s d, F) with s = Kc (1 when Kc = 0), so that it crosses zero upward exactly when
    // d > 0 and F > 0 become both true; closed: -F.
    [[nodiscard]] double switching_function(const ElementState& s, int mode) const override;
    [[nodiscard]] int mode_after_switch(int mode) const override { return 1 - mode; }
    // Closed where it penetrates (statically F = Kc d); a relative 1e-12 of the lengths in play
    // counts as touching, not penetrating.
    [[nodiscard]] int static_mode(const ElementState& s) const override;
    // Closed where d > 0 and F > 0, and where it touches (d = 0 to roundoff) and moves in.
    [[nodiscard]] int initial_mode(const ElementState& s) const override;

    // 0: dd/dt (direction -1: maxima of d); 1: dF/dt while closed (maxima of F), 1 while open.
    [[nodiscard]] int watch_count() const override { return 2; }
    void watch_functions(const ElementState& s, int mode, double* g) const override;
    [[nodiscard]] std::vector<int> watch_directions() const override { return {-1, -1}; }
    [[nodiscard]] bool watch_needs_acceleration(int mode) const override { return mode == 1; }

    [[nodiscard]] std::optional<LinearForm> linear_form() const override;

    [[nodiscard]] bool is_contact() const override { return true; }
    [[nodiscard]] int contact_mode() const override { return 1; }
    [[nodiscard]] ContactReading contact_reading(const ElementState& s) const override;
    [[nodiscard]] double position() const override { return x_; }

    [[nodiscard]] double penetration(const ElementState& s) const { return sign_ * (surface_ - s.q[0]); }
    [[nodiscard]] double penetration_rate(const ElementState& s) const { return -sign_ * s.v[0]; }
    [[nodiscard]] double force_magnitude(const ElementState& s) const {
        return stiffness_ * penetration(s) + damping_ * penetration_rate(s);
    }

private:
    std::string name_;
    std::vector<int> dofs_;
    double sign_, surface_, stiffness_, damping_, x_;
};

}  // namespace vi
