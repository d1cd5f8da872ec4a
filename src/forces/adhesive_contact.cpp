#include "forces/adhesive_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vi {

AdhesiveContact::AdhesiveContact(std::string name, int dof, double sign, double surface, double stiffness,
                                 double damping, double x, double pull_off, double range, std::string law)
    : name_(std::move(name)), dofs_{dof}, sign_(sign), surface_(surface), stiffness_(stiffness), damping_(damping),
      x_(x), pull_off_(pull_off), range_(range), law_(std::move(law)) {
    if (dof < 0 || std::abs(sign) != 1.0 || !std::isfinite(surface) || !(stiffness > 0.0) || !std::isfinite(stiffness) ||
        !(damping >= 0.0) || !std::isfinite(damping) || !(pull_off > 0.0) || !std::isfinite(pull_off) ||
        !(range > 0.0) || !std::isfinite(range)) {
        throw std::invalid_argument(name_ + ": inconsistent adhesive contact data");
    }
    d_po_ = -pull_off_ / stiffness_;
    d_end_ = d_po_ - range_;
}

std::string AdhesiveContact::kind() const { return "adhesive contact (" + law_ + ")"; }

double AdhesiveContact::attraction(double d) const {
    return pull_off_ * std::clamp((d - d_end_) / range_, 0.0, 1.0);
}

void AdhesiveContact::add_force(const ElementState& s, int mode, double* f) const {
    f[0] += sign_ * (mode == 1 ? closed_force(s) : -attraction(penetration(s)));
}

void AdhesiveContact::add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const {
    if (mode == 1) {
        dfdq[0] -= stiffness_;
        dfdv[0] -= damping_;
        return;
    }
    // f = -sign A(d), dd/dq = -sign: df/dq = A'(d) = F_po / range inside the zone.
    const double d = penetration(s);
    if (d > d_end_ && d < d_po_) dfdq[0] += pull_off_ / range_;
}

double AdhesiveContact::stored_energy(const ElementState& s, int mode) const {
    const double d = penetration(s);
    const double zone = 0.5 * pull_off_ * range_;
    if (mode == 1) return 0.5 * stiffness_ * d * d - 0.5 * pull_off_ * pull_off_ / stiffness_ - zone;
    if (d <= d_end_) return 0.0;
    if (d >= d_po_) return -zone - pull_off_ * (d - d_po_);
    return -0.5 * pull_off_ * (d - d_end_) * (d - d_end_) / range_;
}

double AdhesiveContact::dissipated_power(const ElementState& s, int mode) const {
    if (mode != 1) return 0.0;
    return damping_ * s.v[0] * s.v[0];
}

double AdhesiveContact::switching_function(const ElementState& s, int mode) const {
    const double F = closed_force(s);
    if (mode == 1) return -(F + pull_off_);
    return std::min(stiffness_ * (penetration(s) - d_po_), F + pull_off_);
}

int AdhesiveContact::static_mode(const ElementState& s) const {
    const double tol = 1e-12 * std::max({std::abs(surface_), std::abs(s.q[0]), std::abs(d_po_)});
    return penetration(s) - d_po_ > tol ? 1 : 0;
}

int AdhesiveContact::initial_mode(const ElementState& s) const {
    const double d = penetration(s);
    if (d > d_po_ && closed_force(s) + pull_off_ > 0.0) return 1;
    const double scale = std::max({std::abs(surface_), std::abs(s.q[0]), std::abs(d_po_)});
    const bool touching = std::abs(d - d_po_) <= 64.0 * std::numeric_limits<double>::epsilon() * scale;
    return touching && -sign_ * s.v[0] > 0.0 ? 1 : 0;
}

void AdhesiveContact::watch_functions(const ElementState& s, int mode, double* g) const {
    g[0] = -sign_ * s.v[0];
    g[1] = mode == 1 && s.a ? stiffness_ * g[0] - damping_ * sign_ * s.a[0] : 1.0;
    g[2] = mode == 1 ? 1.0 : penetration(s) - d_end_;
}

ContactReading AdhesiveContact::contact_reading(const ElementState& s) const {
    return {penetration(s), closed_force(s), s.v[0]};
}

}  // namespace vi
