#include "forces/adhesive_layer_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vi {
namespace {

// The largest pull q for which the well's depth is W. Where f = 0: d_0 = sqrt(2 r q / k) while
// q <= k r / 2 (inside the quadratic part), then d_0 = q / k + r / 2. The depth is
//   q r / 2 + (2/3) q d_0                     for q <= k r / 2,
//   q^2 / (2 k) + q r - k r^2 / 24            above (7 k r^2 / 12 at the boundary, from both).
double pull_for_depth(double k, double W, double r) {
    if (W >= 7.0 * k * r * r / 12.0) {
        // q^2 / (2 k) + q r - (W + k r^2 / 24) = 0, in the form that does not cancel.
        const double c = W + k * r * r / 24.0;
        return 2.0 * c / (r + std::sqrt(r * r + 2.0 * c / k));
    }
    // With s = sqrt(q): F(s) = a s^3 + (r / 2) s^2 - W, a = (2/3) sqrt(2 r / k), increasing and convex
    // for s > 0, so Newton's method from an upper bound falls monotonically onto the root. Either
    // term alone equal to W bounds s from above.
    const double a = (2.0 / 3.0) * std::sqrt(2.0 * r / k);
    double s = std::min(std::sqrt(2.0 * W / r), std::cbrt(W / a));
    for (int it = 0; it < 200; ++it) {
        const double F = (a * s + 0.5 * r) * s * s - W;
        const double dF = (3.0 * a * s + r) * s;
        const double next = s - F / dF;
        if (!(next < s)) break;  // monotone descent has reached rounding
        s = next;
    }
    return s * s;
}

}  // namespace

AdhesiveLayerLaw::AdhesiveLayerLaw(double line_stiffness, double adhesion_energy, double range)
    : k_(line_stiffness), w_(adhesion_energy), r_(range) {
    if (!(k_ > 0.0) || !std::isfinite(k_) || !(w_ > 0.0) || !std::isfinite(w_) || !(r_ > 0.0) || !std::isfinite(r_)) {
        throw std::invalid_argument("AdhesiveLayerLaw: stiffness, adhesion energy and range must be positive and finite");
    }
    q_ = pull_for_depth(k_, w_, r_);
    d0_ = q_ <= 0.5 * k_ * r_ ? std::sqrt(2.0 * r_ * q_ / k_) : q_ / k_ + 0.5 * r_;
}

AdhesiveLayerLaw::Value AdhesiveLayerLaw::at(double d) const {
    Value v;
    if (d <= -r_) return v;
    if (d < 0.0) {
        const double t = (d + r_) / r_;
        v.force = -q_ * t * t * (3.0 - 2.0 * t);
        v.slope = -q_ * 6.0 * t * (1.0 - t) / r_;
        v.energy = -q_ * r_ * t * t * t * (1.0 - 0.5 * t);
        return v;
    }
    if (d < r_) {
        v.force = -q_ + 0.5 * k_ * d * d / r_;
        v.slope = k_ * d / r_;
        v.energy = -q_ * (0.5 * r_ + d) + k_ * d * d * d / (6.0 * r_);
        return v;
    }
    const double e = d - r_;
    v.force = k_ * d - q_ - 0.5 * k_ * r_;
    v.slope = k_;
    // phi(r) + int_r^d f: the integrand is (k r / 2 - q) + k (x - r).
    v.energy = -1.5 * q_ * r_ + k_ * r_ * r_ / 6.0 + (0.5 * k_ * r_ - q_) * e + 0.5 * k_ * e * e;
    return v;
}

}  // namespace vi
