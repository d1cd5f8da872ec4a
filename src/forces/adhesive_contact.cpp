#include "forces/adhesive_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vi {

AdhesiveContact::AdhesiveContact(std::string name, int dof, double sign, double surface, double stiffness,
                                 double damping, double x, double pull_off, double range, std::string law)
    : UnilateralContact(std::move(name), dof, sign, surface, stiffness, damping, x, pull_off), range_(range),
      law_(std::move(law)) {
    if (!(stiffness > 0.0) || !(pull_off > 0.0) || !std::isfinite(pull_off) || !(range > 0.0) || !std::isfinite(range)) {
        throw std::invalid_argument(name_ + ": inconsistent adhesive contact data");
    }
    d_end_ = d_po_ - range_;
}

std::string AdhesiveContact::kind() const { return "adhesive contact (" + law_ + ")"; }

double AdhesiveContact::attraction(double d) const {
    return pull_off_ * std::clamp((d - d_end_) / range_, 0.0, 1.0);
}

void AdhesiveContact::add_open_force(const ElementState& s, double* f) const {
    f[0] += sign_ * -attraction(penetration(s));
}

void AdhesiveContact::add_open_tangent(const ElementState& s, double* dfdq) const {
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

void AdhesiveContact::watch_functions(const ElementState& s, int mode, double* g) const {
    UnilateralContact::watch_functions(s, mode, g);
    g[2] = mode == 1 ? 1.0 : penetration(s) - d_end_;
}

}  // namespace vi
