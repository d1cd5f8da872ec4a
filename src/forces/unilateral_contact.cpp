#include "forces/unilateral_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vi {

UnilateralContact::UnilateralContact(std::string name, int dof, double sign, double surface, double stiffness,
                                     double damping, double x, double pull_off)
    : PointContact(std::move(name), dof, sign, surface, x), stiffness_(stiffness), damping_(damping),
      pull_off_(pull_off), d_po_(pull_off > 0.0 ? -pull_off / stiffness : 0.0) {
    if (dof < 0 || std::abs(sign) != 1.0 || !std::isfinite(surface) || !(stiffness >= 0.0) ||
        !std::isfinite(stiffness) || !(damping >= 0.0) || !std::isfinite(damping) || !(pull_off >= 0.0)) {
        throw std::invalid_argument(name_ + ": inconsistent contact data");
    }
}

void UnilateralContact::add_force(const ElementState& s, int mode, double* f) const {
    if (mode == 1) {
        f[0] += sign_ * force_magnitude(s);
    } else {
        add_open_force(s, f);
    }
}

void UnilateralContact::add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const {
    // Closed: f = sign (Kc sign (surface - q) - Cc sign v) = Kc (surface - q) - Cc v.
    if (mode != 1) {
        add_open_tangent(s, dfdq);
        return;
    }
    dfdq[0] -= stiffness_;
    dfdv[0] -= damping_;
}

double UnilateralContact::dissipated_power(const ElementState& s, int mode) const {
    if (mode != 1) return 0.0;
    const double r = penetration_rate(s);
    return damping_ * r * r;
}

double UnilateralContact::switching_function(const ElementState& s, int mode) const {
    const double F = force_magnitude(s);
    if (mode == 1) return -(F + pull_off_);
    const double scale = stiffness_ > 0.0 ? stiffness_ : 1.0;
    return std::min(scale * (penetration(s) - d_po_), F + pull_off_);
}

int UnilateralContact::static_mode(const ElementState& s) const {
    const double tol = 1e-12 * std::max({std::abs(surface_), std::abs(s.q[0]), std::abs(d_po_)});
    return penetration(s) - d_po_ > tol ? 1 : 0;
}

int UnilateralContact::initial_mode(const ElementState& s) const {
    const double d = penetration(s);
    if (d > d_po_ && force_magnitude(s) + pull_off_ > 0.0) return 1;
    const double scale = std::max({std::abs(surface_), std::abs(s.q[0]), std::abs(d_po_)});
    const bool touching = std::abs(d - d_po_) <= 64.0 * std::numeric_limits<double>::epsilon() * scale;
    return touching && penetration_rate(s) > 0.0 ? 1 : 0;
}

void UnilateralContact::watch_functions(const ElementState& s, int mode, double* g) const {
    g[0] = penetration_rate(s);
    // dF/dt = Kc dd/dt + Cc d2d/dt2, d2d/dt2 = -sign a.
    g[1] = mode == 1 && s.a ? stiffness_ * g[0] - damping_ * sign_ * s.a[0] : 1.0;
}

ContactReading UnilateralContact::contact_reading(const ElementState& s) const {
    return {penetration(s), force_magnitude(s), s.v[0]};
}

}  // namespace vi
