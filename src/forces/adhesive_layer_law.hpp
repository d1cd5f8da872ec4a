#pragma once
// AdhesiveLayerLaw: the line force of an adhesive dielectric layer on the beam, per unit length, as
// one C1 function of the penetration with one energy: the layer's elastic foundation and a
// finite-range attraction whose potential well is exactly the adhesion energy (docs/adhesion.md §9).

namespace vi {

// With d the penetration into the layer's face [m] (> 0 pressed in), k the layer's line stiffness
// [N/m^2], W = w w_e the adhesion energy per unit length [J/m] and r the range [m]:
//   d <= -r:      f = 0 (out of range: the beam is free);
//   -r < d < 0:   f = -q s(t), t = (d + r) / r, s = 3 t^2 - 2 t^3 (the attraction, rising smoothly to q);
//   0 <= d < r:   f = -q + k d^2 / (2 r) (the layer's stiffness comes in over the same range);
//   d >= r:       f = k d - q - k r / 2 (the layer's spring, offset by the pull).
// f pushes the beam out of the layer (negative: it pulls). The energy phi (dphi/dd = f, phi = 0 out
// of range) is least where f = 0 (d_0, inside the pressed part) and q, the largest pull (at the
// face), is chosen so that phi(d_0) = -W exactly: separating a point at rest takes the work of
// adhesion, whatever the layer's stiffness and the range.
class AdhesiveLayerLaw {
public:
    AdhesiveLayerLaw(double line_stiffness, double adhesion_energy, double range);

    struct Value {
        double force = 0.0;   // f [N/m]
        double slope = 0.0;   // df/dd [N/m^2]
        double energy = 0.0;  // phi [J/m]
    };
    [[nodiscard]] Value at(double d) const;

    [[nodiscard]] double stiffness() const { return k_; }
    [[nodiscard]] double adhesion_energy() const { return w_; }
    [[nodiscard]] double range() const { return r_; }
    // q: the largest pull [N/m], at the face (d = 0).
    [[nodiscard]] double largest_pull() const { return q_; }
    // d_0: where a point rests with no other force (f = 0, phi = -W) [m].
    [[nodiscard]] double rest_penetration() const { return d0_; }

private:
    double k_, w_, r_;
    double q_ = 0.0, d0_ = 0.0;
};

}  // namespace vi
