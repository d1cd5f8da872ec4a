#pragma once
// ElectrostaticPad: the distributed electrostatic force of one electrode on the span of the beam it
// faces, integrated on the beam's Hermite shape functions by Gauss quadrature (docs/electrostatics.md).

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "forces/force_element.hpp"
#include "model/case.hpp"
#include "model/time_function.hpp"

namespace vi {

// One quadrature point: its place [m], the length it stands for [m], and the Hermite shape values
// of v there on (v1, theta1, v2, theta2) of its beam element [-, m], with the index of each of those
// DOFs in the pad's dofs() (-1 where an end condition holds the DOF).
struct PadPoint {
    double x = 0.0;
    double weight = 0.0;
    std::array<int, 4> local{-1, -1, -1, -1};
    std::array<double, 4> shape{};
};

// v at the point from the DOFs q (in the order the point's local indices refer to) [m]. Inline,
// as the two below: distributed elements call them at every quadrature point of every evaluation.
inline double point_displacement(const PadPoint& p, const double* q) {
    double v = 0.0;
    for (int i = 0; i < 4; ++i) {
        if (p.local[i] >= 0) v += p.shape[i] * q[p.local[i]];
    }
    return v;
}
// Consecutive points on the same element's DOFs: the hot loops (a pad's force and capacitance, a
// layer's deepest point) gather those four DOFs once per run, not at each of its Gauss points.
struct PointRun {
    std::array<int, 4> local{-1, -1, -1, -1};
    std::size_t begin = 0, end = 0;  // [begin, end) in the points
};
std::vector<PointRun> point_runs(const std::vector<PadPoint>& points);
// The element's DOFs of run r from q, 0 where an end condition holds one.
inline std::array<double, 4> run_dofs(const PointRun& r, const double* q) {
    std::array<double, 4> out{};
    for (int i = 0; i < 4; ++i) out[i] = r.local[i] >= 0 ? q[r.local[i]] : 0.0;
    return out;
}
// point_displacement at a point of a run, from run_dofs: the same number (a held DOF adds a zero).
inline double run_displacement(const PadPoint& p, const std::array<double, 4>& qe) {
    return p.shape[0] * qe[0] + p.shape[1] * qe[1] + p.shape[2] * qe[2] + p.shape[3] * qe[3];
}
// Adds a transverse load [N] at the point to the generalised forces f (its shape functions).
inline void add_point_load(const PadPoint& p, double load, double* f) {
    for (int i = 0; i < 4; ++i) {
        if (p.local[i] >= 0) f[p.local[i]] += load * p.shape[i];
    }
}
// Adds k N_i N_j [N/m] at the point to the row-major n x n tangent dfdq.
inline void add_point_stiffness(const PadPoint& p, double k, std::size_t n, double* dfdq) {
    for (int i = 0; i < 4; ++i) {
        if (p.local[i] < 0) continue;
        for (int j = 0; j < 4; ++j) {
            if (p.local[j] < 0) continue;
            dfdq[static_cast<std::size_t>(p.local[i]) * n + static_cast<std::size_t>(p.local[j])] += k * p.shape[i] * p.shape[j];
        }
    }
}

// The electrode as the force sees it. Electrical gap at a point: g_e = (gap - t_d) - sign v + t_d /
// eps_r, with sign = +1 for an electrode above (it pulls +v), -1 below.
struct PadGeometry {
    double sign = -1.0;
    double gap = 0.0;                      // electrode to beam at rest, dielectric included [m]
    double dielectric_thickness = 0.0;     // t_d [m]
    double dielectric_permittivity = 1.0;  // eps_r [-]
    double width = 0.0;                    // w_e [m]
    double beam_thickness = 0.0;           // t, for the fringing model [m]
    Fringing fringing = Fringing::none;
    double from = 0.0, to = 0.0;           // the span [m]
};

// Vacuum permittivity [F/m] (CODATA 2018).
inline constexpr double kEpsilon0 = 8.8541878128e-12;

// A bare electrode's collapse: the beam has reached the electrode once its narrowest air gap falls
// to this fraction of the gap at rest. Why 1 %: there the parallel-plate pull is 10^4 times its value
// at rest, and an elastic restoring force able to hold the beam would need V below about
// sqrt(27/4) 0.01 = 2.6 % of the 1-DOF pull-in voltage (k (1 - f) g = eps0 A V^2 / (2 f^2 g^2) at f =
// 0.01), so a beam that gets there under any working voltage does not come back; the rest of the way,
// a travel of 1 % of the gap under a force growing like 1/gap^2, takes a vanishing time (the 1-DOF
// plate's remaining time scales like f^(3/2)). Following it further only makes the integrator creep
// toward the singular face (docs/electrostatics.md §2). It lies above the squeeze film's guard (1e-3
// of its gap), so the collapse is found first.
inline constexpr double kCollapseGapFraction = 0.01;

// Gauss-Legendre points per beam element (or part of one) the pad integrates with.
inline constexpr int kPadGaussPoints = 8;

// Capacitance per unit length c(g_e) [F/m] of a strip of width w over a plane, and its first two
// derivatives in g_e: parallel plate eps0 w / g, or Meijs-Fokkema's line-to-ground formula
// eps0 (w/g + 0.77 + 1.06 (w/g)^0.25 + 1.06 (t/g)^0.5).
struct LineCapacitance {
    double c = 0.0, dc = 0.0, d2c = 0.0;
};
// Adds Meijs-Fokkema's fringing terms to a parallel-plate c (the slow part, out of line).
void add_fringing(const PadGeometry& g, double gap, LineCapacitance& out);
// Inline because it runs at every quadrature point of every right-hand side.
inline LineCapacitance line_capacitance(const PadGeometry& g, double gap) {
    LineCapacitance out;
    const double inverse = 1.0 / gap;
    out.c = kEpsilon0 * g.width * inverse;
    out.dc = -out.c * inverse;
    out.d2c = -2.0 * out.dc * inverse;
    if (g.fringing == Fringing::meijs_fokkema) add_fringing(g, gap, out);
    return out;
}

// Line loads over the span of `points` (on n DOFs) constant, linear and quadratic in x: the shapes
// an electrode's force and its dielectric's contact take, for a reduced-order model's corrections.
std::vector<std::vector<double>> line_load_patterns(const std::vector<PadPoint>& points, const PadGeometry& g,
                                                    std::size_t n);
// The same over the span [from, to] [m] (a squeeze film's).
std::vector<std::vector<double>> line_load_patterns(const std::vector<PadPoint>& points, double from, double to,
                                                    std::size_t n);

// The pad: V(t) = voltage g(t). Stored energy is the electrical co-energy's negative, -C V^2 / 2
// (its gradient is minus the force, as the force-element contract asks); the source's input power
// in that ledger is -C V dV/dt (docs/electrostatics.md §3).
// A bare electrode (no dielectric) has two modes: 0, the beam clear of it, and 1, collapsed, a
// terminal mode (ForceElement::ends_run) entered when the narrowest air gap falls to
// kCollapseGapFraction of the gap; the force is the same in both. With a dielectric layer the
// layer's contact (DielectricContact) stops the beam, and the pad has one mode.
class ElectrostaticPad final : public ForceElement {
public:
    ElectrostaticPad(std::string name, std::vector<int> dofs, std::vector<PadPoint> points, PadGeometry geometry,
                     double voltage, TimeFunction time);

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override { return "electrostatic pad"; }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }
    [[nodiscard]] int modes() const override { return collapse_gap_ > 0.0 ? 2 : 1; }

    // Clear: (collapse gap - narrowest air gap) / gap, rising through 0 as the beam reaches the
    // collapse gap; collapsed: -1 (the run has ended).
    [[nodiscard]] double switching_function(const ElementState& s, int mode) const override;
    [[nodiscard]] int mode_after_switch(int /*mode*/) const override { return 1; }
    // Collapsed from the start when the beam already lies within the collapse gap.
    [[nodiscard]] int initial_mode(const ElementState& s) const override;
    [[nodiscard]] bool ends_run(int mode) const override { return mode == 1 && collapse_gap_ > 0.0; }
    // "collapsed", the place of the narrowest air gap, that gap, and a sentence with the voltage.
    [[nodiscard]] RunEnd run_end(const ElementState& s) const override;
    // The air gap at which the beam counts as collapsed onto the electrode [m]; 0 with a dielectric.
    [[nodiscard]] double collapse_gap() const { return collapse_gap_; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const override;
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;
    [[nodiscard]] StoredEnergyKind stored_energy_kind() const override { return StoredEnergyKind::electrical; }
    [[nodiscard]] double dissipated_power(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double input_power(const ElementState& s, int mode) const override;
    // Acts from t = 0 on: the static state a transient starts from is without voltage.
    [[nodiscard]] bool in_static_state() const override { return false; }
    [[nodiscard]] double force_scale() const override;
    [[nodiscard]] std::vector<double> time_stops(double t0, double t1) const override { return time_.stops(t0, t1); }
    [[nodiscard]] double position() const override { return 0.5 * (geometry_.from + geometry_.to); }
    // A line load over the span that is constant, linear and quadratic in x: the shapes the force
    // takes as the gap closes unevenly, for a reduced-order model's static corrections.
    [[nodiscard]] std::vector<std::vector<double>> load_patterns() const override;
    // On a basis: the basis' values at the quadrature points, kept, so that a force costs two
    // products of that Nq x r matrix and a tangent one weighted product (electrostatic_pad_reduced.cpp).
    [[nodiscard]] std::unique_ptr<const ReducedElement> reduced(const BasisRows& rows) const override;

    // V(t) [V].
    [[nodiscard]] double voltage(double t) const { return voltage_ * time_(t); }
    // Capacitance between electrode and beam at displacements q (the pad's DOFs) [F].
    [[nodiscard]] double capacitance(const double* q) const;
    // The smallest air gap over the span, beam to the dielectric's face [m], and where it is [m].
    struct Narrowest {
        double air_gap = 0.0;
        double x = 0.0;
    };
    [[nodiscard]] Narrowest narrowest(const double* q) const;
    // Weights r over dofs() such that r . q is the mean travel toward the electrode over the span [m].
    [[nodiscard]] std::vector<double> mean_travel_row() const;
    [[nodiscard]] const PadGeometry& geometry() const { return geometry_; }

private:
    friend class ReducedPad;

    // g_e at point k; inline, as it runs at every quadrature point of every right-hand side.
    [[nodiscard]] double electrical_gap(const PadPoint& p, const double* q) const {
        return rest_gap_ - geometry_.sign * point_displacement(p, q);
    }
    // Throws std::domain_error when the beam reaches a bare electrode's face (no force is defined
    // there) or presses through half a dielectric's electrical thickness.
    void require_open(const PadPoint& p, double ge) const {
        if (!(ge > open_above_)) refuse(p, ge);
    }
    [[noreturn]] void refuse(const PadPoint& p, double ge) const;

    // g_e at a point of a run, from run_dofs.
    [[nodiscard]] double run_gap(const PadPoint& p, const std::array<double, 4>& qe) const {
        return rest_gap_ - geometry_.sign * run_displacement(p, qe);
    }

    std::string name_;
    std::vector<int> dofs_;
    std::vector<PadPoint> points_;
    std::vector<PointRun> runs_;  // point_runs(points_)
    PadGeometry geometry_;
    double voltage_;
    TimeFunction time_;
    double layer_ = 0.0;       // the dielectric's electrical thickness t_d / eps_r [m]
    double rest_gap_ = 0.0;    // g_e at v = 0 [m]
    double open_above_ = 0.0;  // require_open passes for g_e above this [m]
    double collapse_gap_ = 0.0;  // kCollapseGapFraction of a bare electrode's gap [m]; 0 with a layer
};

}  // namespace vi
