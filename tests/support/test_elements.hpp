#pragma once
// Force elements that exist only for tests: a hardening cubic spring on one DOF, f = -k3 q^3, with
// no piecewise-linear form (it rules the exact solver out and exercises the nonlinear path).

#include <cmath>
#include <string>
#include <vector>

#include "forces/force_element.hpp"

namespace vi::test {

class CubicSpring final : public ForceElement {
public:
    CubicSpring(int dof, double k3) : dofs_{dof}, k3_(k3) {}
    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override { return "cubic spring"; }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }
    void add_force(const ElementState& s, int, double* f) const override { f[0] -= k3_ * s.q[0] * s.q[0] * s.q[0]; }
    void add_tangent(const ElementState& s, int, double* dq, double*) const override { dq[0] -= 3.0 * k3_ * s.q[0] * s.q[0]; }
    [[nodiscard]] double stored_energy(const ElementState& s, int) const override {
        return 0.25 * k3_ * std::pow(s.q[0], 4);
    }
    [[nodiscard]] double dissipated_power(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double input_power(const ElementState&, int) const override { return 0.0; }

private:
    std::string name_ = "springs[0]";
    std::vector<int> dofs_;
    double k3_;  // [N/m^3]
};

}  // namespace vi::test
