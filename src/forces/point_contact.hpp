#pragma once
// PointContact: what every support law shares, whatever its force: a surface facing the transverse
// DOF of one node, open (mode 0) or closed (mode 1), its penetration and rate, the watch of the
// largest penetration and force, and its place in messages and output. The laws (UnilateralContact
// and its kinds, HertzContact) give the force, its tangent, energy, power and switching rules.

#include <string>
#include <utility>
#include <vector>

#include "forces/force_element.hpp"

namespace vi {

// Surface at height `surface` [m] on side `sign` (+1 below the beam, -1 above) at x [m] along the
// beam; penetration d = sign (surface - q) [m] of the beam's DOF `dof`, positive inside the surface.
class PointContact : public ForceElement {
public:
    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }
    [[nodiscard]] int modes() const override { return 2; }
    [[nodiscard]] double input_power(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] int mode_after_switch(int mode) const override { return 1 - mode; }

    // 0: dd/dt (direction -1: maxima of d); 1: dF/dt while closed (maxima of F), 1 while open.
    [[nodiscard]] int watch_count() const override { return 2; }
    [[nodiscard]] std::vector<int> watch_directions() const override { return {-1, -1}; }
    [[nodiscard]] bool watch_needs_acceleration(int mode) const override { return mode == 1; }

    [[nodiscard]] bool is_contact() const override { return true; }
    [[nodiscard]] int contact_mode() const override { return 1; }
    [[nodiscard]] double position() const override { return x_; }

    [[nodiscard]] double penetration(const ElementState& s) const { return sign_ * (surface_ - s.q[0]); }
    [[nodiscard]] double penetration_rate(const ElementState& s) const { return -sign_ * s.v[0]; }

protected:
    PointContact(std::string name, int dof, double sign, double surface, double x)
        : name_(std::move(name)), dofs_{dof}, sign_(sign), surface_(surface), x_(x) {}

    std::string name_;
    std::vector<int> dofs_;
    double sign_, surface_, x_;
};

}  // namespace vi
