#pragma once
// MidplaneStretching: the axial force a beam held at both ends gains as it bends (its axis
// lengthens), N = (E A / (2 l)) int v'^2 dx = (E A / (2 l)) q^T G q, acting through the slope on
// every bending DOF (docs/electrostatics.md §8).

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "forces/element_family.hpp"
#include "forces/force_element.hpp"

namespace vi {

// The element on DOFs 0 .. n-1 of G. Force f = -N(q) G q [N, N m]; tangent -N G - (E A / l) (G q)(G q)^T;
// stored energy (E A / (8 l)) (q^T G q)^2 [J] (the strain energy of the stretch N^2 l / (2 E A)).
class MidplaneStretching final : public ForceElement {
public:
    // g: int N_i' N_j' dx over the element's DOFs [1/m] (symmetric, positive semidefinite);
    // axial_stiffness: E A / l [N/m].
    MidplaneStretching(std::string name, Eigen::SparseMatrix<double> g, double axial_stiffness);

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override { return "mid-plane stretching"; }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const override;
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;
    // The stretch is strain energy of the beam: the ledger counts it with q^T K q / 2.
    [[nodiscard]] StoredEnergyKind stored_energy_kind() const override { return StoredEnergyKind::strain; }
    // None: its force -N G q is carried by the bending modes themselves (it stiffens them), and a
    // unit force at each of its DOFs, the default, would keep every DOF of the beam in a reduced model.
    [[nodiscard]] std::vector<std::vector<double>> load_patterns() const override { return {}; }
    [[nodiscard]] double dissipated_power(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double input_power(const ElementState&, int) const override { return 0.0; }

    // The stretching force N(q) = (E A / (2 l)) q^T G q [N] at displacements q (dofs() order).
    [[nodiscard]] double axial_force(const double* q) const;

private:
    // G q (|dofs| entries).
    [[nodiscard]] Eigen::VectorXd slope_product(const double* q) const;

    std::string name_;
    std::vector<int> dofs_;
    Eigen::SparseMatrix<double> g_;
    double axial_stiffness_;
};

// The stretching's family: one element "beam.stretching" on every bending DOF when beam.stretching is
// on, its E the modulus bending uses.
const ElementFamily& beam_stretching();

}  // namespace vi
