#pragma once
// AdhesiveContact: a support's unilateral contact that also holds the beam with a pull-off force,
// released through a cohesive zone of finite range (docs/adhesion.md).

#include <string>
#include <vector>

#include "forces/unilateral_contact.hpp"

namespace vi {

// The contact of UnilateralContact with F_po > 0: closed, it may pull (F < 0) down to -F_po; open, the
// surfaces attract with a force that falls linearly from F_po at d_po = -F_po / Kc (the spring's
// stretch at pull-off) to 0 at d_end = d_po - range, the same on approach and on separation, so the
// law has a potential.
class AdhesiveContact final : public UnilateralContact {
public:
    // pull_off: F_po [N] > 0; range: the cohesive zone's width [m] > 0; Kc > 0; law: "DMT" or "JKR"
    // (for kind()).
    AdhesiveContact(std::string name, int dof, double sign, double surface, double stiffness, double damping,
                    double x, double pull_off, double range, std::string law);

    [[nodiscard]] std::string kind() const override;
    // Open: the cohesive zone's potential, -F_po (d - d_end)^2 / (2 range) inside it; closed:
    // Kc d^2 / 2 minus the work of separation F_po^2 / (2 Kc) + F_po range / 2 [J]. Both are the
    // same function where the modes meet (d = d_po), so a switch there stores nothing.
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;

    // 0, 1: the contact's; 2: d - d_end while open (the end of the adhesion range, where the
    // attraction kinks to zero: located, so no step straddles it).
    [[nodiscard]] int watch_count() const override { return 3; }
    void watch_functions(const ElementState& s, int mode, double* g) const override;
    [[nodiscard]] std::vector<int> watch_directions() const override { return {-1, -1, 0}; }

    // The attraction of the open contact [N] (>= 0) at penetration d.
    [[nodiscard]] double attraction(double d) const;

private:
    void add_open_force(const ElementState& s, double* f) const override;
    void add_open_tangent(const ElementState& s, double* dfdq) const override;

    double range_;
    double d_end_;  // where the cohesive zone ends [m]
    std::string law_;
};

}  // namespace vi
