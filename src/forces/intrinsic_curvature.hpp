#pragma once
// IntrinsicCurvature: the stress-free curvature kappa0 [1/m] of a released beam (a stress gradient
// through its thickness: the curl of a cantilever), as the constant load it puts on the straight
// beam's DOFs; its family, which makes it from the case's [curl] table, and that table's keys.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "forces/element_family.hpp"
#include "fem/system.hpp"
#include "forces/force_element.hpp"

namespace vi {

// The strain energy (1/2) EI (w'' - kappa0)^2 is (1/2) EI w''^2, which K holds, minus EI kappa0 w''
// (plus a constant): a load f = EI kappa0 int N''^T dx, over each element the moments -EI kappa0 and
// +EI kappa0 on its two rotations [N m]. It is linear in q, so its tangent is zero, its stored energy
// -f.q [J] (the ledger's strain energy), and it neither dissipates nor takes in power. It acts in
// the static state, so a transient starts from the released shape and gaps are measured from the
// straight beam.
class IntrinsicCurvature final : public ForceElement {
public:
    // dofs: the bending DOFs it acts on; load: f on them [N m] (finite).
    IntrinsicCurvature(std::string name, std::vector<int> dofs, std::vector<double> load);

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override { return "intrinsic curvature"; }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState&, int, double*, double*) const override {}
    // -f.q [J]: with K's (1/2) q K q, the beam's strain energy less its constant part.
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;
    [[nodiscard]] StoredEnergyKind stored_energy_kind() const override { return StoredEnergyKind::strain; }
    [[nodiscard]] double dissipated_power(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double input_power(const ElementState&, int) const override { return 0.0; }
    // Its one load shape (not a unit force at each of the many DOFs it touches).
    [[nodiscard]] std::vector<std::vector<double>> load_patterns() const override { return {load_}; }
    [[nodiscard]] double force_scale() const override;
    // A constant forcing: the exact solver books its work as that of a load.
    [[nodiscard]] std::optional<LinearForm> linear_form() const override;

private:
    std::string name_;
    std::vector<int> dofs_;
    std::vector<double> load_;
};

// The stress-free curvature kappa0 [1/m] the [curl] table of c gives: its curvature, its
// stress_gradient Gamma over the bending modulus E (kappa0 = Gamma / E), or its tip_lift delta over
// the beam's length (kappa0 = 2 delta / l^2); 0 without the table.
double intrinsic_curvature(const Case& c);

// The released curl's load on the reduced DOFs of s [N m]: on every element its section's EI kappa0
// (kappa0 from [curl]) plus its layers' stress moment M_r, as moments -M and +M on its two rotations.
Eigen::VectorXd curl_load(const Case& c, const System& s);

// v(x) [m] of the unloaded beam of c released with curvature kappa0 [1/m] at x [m]: the cubic with
// w'' = kappa0 at its free and pinned ends (no moment), w''' = 0 at a free end, w = 0 at a held one,
// w' = 0 at a clamped one (a cantilever: kappa0 x^2 / 2; clamped at both ends: 0).
double released_shape(const Case& c, double kappa0, double x);

// The family: an IntrinsicCurvature named "curl" where the case has a [curl] table; it registers
// that table.
const ElementFamily& intrinsic_curvatures();

}  // namespace vi
