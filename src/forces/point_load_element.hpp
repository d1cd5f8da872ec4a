#pragma once
// PointLoadElement: a prescribed transverse point force Q(t) = amplitude g(t), applied through its
// consistent nodal load (the Hermite shape values at the point; docs/model.md §5).

#include <cmath>
#include <string>
#include <vector>

#include "forces/element_family.hpp"
#include "forces/force_element.hpp"
#include "model/time_function.hpp"

namespace vi {

// dofs/weights: the consistent load vector of a unit force at the point (weights [-] on v DOFs,
// [m] on rotation DOFs); amplitude [N]; g(t) dimensionless.
class PointLoadElement final : public ForceElement {
public:
    PointLoadElement(std::string name, std::vector<int> dofs, std::vector<double> weights, double amplitude, TimeFunction g,
              double x);

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override { return "point load"; }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState&, int, double*, double*) const override {}
    [[nodiscard]] double stored_energy(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double dissipated_power(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double input_power(const ElementState& s, int mode) const override;
    [[nodiscard]] bool in_static_state() const override { return false; }
    [[nodiscard]] double force_scale() const override { return std::abs(amplitude_) * g_.max_abs(); }
    [[nodiscard]] std::vector<double> time_stops(double t0, double t1) const override {
        return g_.stops(t0, t1);
    }
    [[nodiscard]] std::optional<LinearForm> linear_form() const override;
    [[nodiscard]] double position() const override { return x_; }

private:
    std::string name_;
    std::vector<int> dofs_;
    std::vector<double> weights_;
    double amplitude_;
    TimeFunction g_;
    double x_;
};

// The loads' family: one element per [[loads]] entry, on the nonzero entries of its consistent load
// vector over the bending DOFs.
const ElementFamily& point_loads();

}  // namespace vi
