#pragma once
// DielectricContact: the distributed unilateral contact of the beam on an electrode's dielectric
// layer, an elastic (Winkler) foundation of line stiffness k = E_d w / t_d under the span, acting
// where the beam presses into the layer (docs/electrostatics.md §2); optionally adhesive (the layer
// also pulls, by AdhesiveLayerLaw: docs/adhesion.md §9).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "forces/adhesive_layer_law.hpp"
#include "forces/electrostatic_pad.hpp"

namespace vi {

// On the points of its electrode's pad: penetration d(x) = sign v(x) - (gap - t_d) [m] (> 0 where
// the beam presses into the layer's face), line force k max(d, 0) [N/m] pushing the beam back.
// Mode 0: open (no point presses; no force); mode 1: closed. It closes when the deepest point's d
// rises through 0 and opens when it falls back through 0 (no damping, so no tension either).
// Adhesive: the line force is AdhesiveLayerLaw's f(d) at every point in both modes (it pulls within
// the range above the face and while pressed in); the modes still say whether some point presses in
// (an episode of the ledger), and the contact lets go when the deepest point leaves the face.
class DielectricContact final : public ForceElement {
public:
    // line_stiffness: k = E_d w_e / t_d [N/m^2]; points and dofs as the pad's (the first DOF the v at
    // the node nearest the span's middle, for the time history's contact column).
    DielectricContact(std::string name, std::vector<int> dofs, std::vector<PadPoint> points, PadGeometry geometry,
                      double line_stiffness);
    // The adhesive layer: `law` carries the line stiffness.
    DielectricContact(std::string name, std::vector<int> dofs, std::vector<PadPoint> points, PadGeometry geometry,
                      const AdhesiveLayerLaw& law);

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override {
        return law_ ? "adhesive dielectric contact" : "dielectric contact";
    }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }
    [[nodiscard]] int modes() const override { return 2; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const override;
    // sum over points of weight k d^2 / 2 where d > 0 (the layer's compression energy) [J]; adhesive:
    // of weight phi(d), negative where the layer holds the beam.
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;
    [[nodiscard]] double dissipated_power(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double input_power(const ElementState&, int) const override { return 0.0; }

    // Open: the deepest penetration; closed: its negative.
    [[nodiscard]] double switching_function(const ElementState& s, int mode) const override;
    [[nodiscard]] int mode_after_switch(int mode) const override { return 1 - mode; }
    [[nodiscard]] int static_mode(const ElementState& s) const override;

    [[nodiscard]] std::vector<std::vector<double>> load_patterns() const override;
    [[nodiscard]] bool is_contact() const override { return true; }
    [[nodiscard]] int contact_mode() const override { return 1; }
    // The deepest penetration, the total force of the layer [N] (adhesive: negative while it pulls)
    // and the velocity of the deepest point.
    [[nodiscard]] ContactReading contact_reading(const ElementState& s) const override;
    [[nodiscard]] double contact_force(const ElementState& s) const override;
    [[nodiscard]] double contact_point_velocity(const ElementState& s) const override;
    [[nodiscard]] double position() const override { return 0.5 * (geometry_.from + geometry_.to); }

    [[nodiscard]] const std::optional<AdhesiveLayerLaw>& adhesion() const { return law_; }
    [[nodiscard]] const PadGeometry& geometry() const { return geometry_; }
    [[nodiscard]] const std::vector<PadPoint>& points() const { return points_; }
    // Inline: the force, tangent and energy loops run it at every point.
    [[nodiscard]] double penetration(const PadPoint& p, const double* q) const {
        return geometry_.sign * point_displacement(p, q) - (geometry_.gap - geometry_.dielectric_thickness);
    }

private:
    // Index of the deepest point.
    [[nodiscard]] std::size_t deepest(const double* q) const;
    // visit(k, penetration(points_[k], q)) for every point in order, each element's DOFs gathered once.
    template <class Visit>
    void for_each_penetration(const double* q, Visit&& visit) const {
        const double depth = geometry_.gap - geometry_.dielectric_thickness;
        for (const PointRun& r : runs_) {
            const std::array<double, 4> qe = run_dofs(r, q);
            for (std::size_t k = r.begin; k < r.end; ++k) visit(k, geometry_.sign * run_displacement(points_[k], qe) - depth);
        }
    }

    std::string name_;
    std::vector<int> dofs_;
    std::vector<PadPoint> points_;
    std::vector<PointRun> runs_;  // point_runs(points_)
    PadGeometry geometry_;
    double stiffness_;
    std::optional<AdhesiveLayerLaw> law_;
};

}  // namespace vi
