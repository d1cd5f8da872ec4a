#pragma once
// AdhesiveContact: a support's Kelvin-Voigt contact that also holds the beam with a pull-off force,
// released through a cohesive zone of finite range (docs/adhesion.md).

#include <string>
#include <vector>

#include "forces/force_element.hpp"

namespace vi {

// The Kelvin-Voigt contact of KelvinVoigtContact (surface at `surface` [m] on side `sign`, Kc [N/m],
// Cc [N s/m]; penetration d = sign (surface - v), closed force F = Kc d + Cc dd/dt) with adhesion:
// closed, the contact may pull (F < 0) down to -F_po and opens only when F falls below -F_po; open,
// the surfaces attract with a force that falls linearly from F_po at d_po = -F_po / Kc (the spring's
// stretch at pull-off) to 0 at d_end = d_po - range, the same on approach and on separation, so the
// law has a potential. Mode 0: open; mode 1: closed. With F_po = 0 it is KelvinVoigtContact.
class AdhesiveContact final : public ForceElement {
public:
    // pull_off: F_po [N] > 0; range: the cohesive zone's width [m] > 0; law: "DMT" or "JKR" (for kind()).
    AdhesiveContact(std::string name, int dof, double sign, double surface, double stiffness, double damping,
                    double x, double pull_off, double range, std::string law);

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override;
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }
    [[nodiscard]] int modes() const override { return 2; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const override;
    // Open: the cohesive zone's potential, -F_po (d - d_end)^2 / (2 range) inside it; closed:
    // Kc d^2 / 2 minus the work of separation F_po^2 / (2 Kc) + F_po range / 2 [J]. Both are the
    // same function where the modes meet (d = d_po), so a switch there stores nothing.
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;
    [[nodiscard]] double dissipated_power(const ElementState& s, int mode) const override;
    [[nodiscard]] double input_power(const ElementState&, int) const override { return 0.0; }

    // Open: min(Kc (d - d_po), F + F_po), which crosses zero upward exactly when both become
    // positive; closed: -(F + F_po).
    [[nodiscard]] double switching_function(const ElementState& s, int mode) const override;
    [[nodiscard]] int mode_after_switch(int mode) const override { return 1 - mode; }
    // Closed where d > d_po (beyond a relative 1e-12 of the lengths in play).
    [[nodiscard]] int static_mode(const ElementState& s) const override;
    [[nodiscard]] int initial_mode(const ElementState& s) const override;

    // 0: dd/dt (maxima of d); 1: dF/dt while closed (maxima of F); 2: d - d_end while open (the end
    // of the adhesion range, where the attraction kinks to zero: located, so no step straddles it).
    [[nodiscard]] int watch_count() const override { return 3; }
    void watch_functions(const ElementState& s, int mode, double* g) const override;
    [[nodiscard]] std::vector<int> watch_directions() const override { return {-1, -1, 0}; }
    [[nodiscard]] bool watch_needs_acceleration(int mode) const override { return mode == 1; }

    [[nodiscard]] bool is_contact() const override { return true; }
    [[nodiscard]] int contact_mode() const override { return 1; }
    // The closed-mode force F, negative while the contact pulls.
    [[nodiscard]] ContactReading contact_reading(const ElementState& s) const override;
    [[nodiscard]] double position() const override { return x_; }

    [[nodiscard]] double pull_off_force() const { return pull_off_; }
    [[nodiscard]] double penetration(const ElementState& s) const { return sign_ * (surface_ - s.q[0]); }
    // The attraction of the open contact [N] (>= 0) at penetration d.
    [[nodiscard]] double attraction(double d) const;

private:
    [[nodiscard]] double closed_force(const ElementState& s) const {
        return stiffness_ * penetration(s) - damping_ * sign_ * s.v[0];
    }

    std::string name_;
    std::vector<int> dofs_;
    double sign_, surface_, stiffness_, damping_, x_, pull_off_, range_;
    double d_po_, d_end_;  // where the cohesive zone starts and ends [m]
    std::string law_;
};

}  // namespace vi
