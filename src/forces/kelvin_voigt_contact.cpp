#include "forces/kelvin_voigt_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vi {

KelvinVoigtContact::KelvinVoigtContact(std::string name, int dof, double sign, double surface, double stiffness,
                                       double damping, double x)
    : name_(std::move(name)), dofs_{dof}, sign_(sign), surface_(surface), stiffness_(stiffness), damping_(damping),
      x_(x) {
    if (dof < 0 || std::abs(sign) != 1.0 || !std::isfinite(surface) || !(stiffness >= 0.0) ||
        !std::isfinite(stiffness) || !(damping >= 0.0) || !std::isfinite(damping)) {
        throw std::invalid_argument(name_ + ": inconsistent Kelvin-Voigt contact data");
    }
}

void KelvinVoigtContact::add_force(const ElementState& s, int mode, double* f) const {
    if (mode == 1) f[0] += sign_ * force_magnitude(s);
}

void KelvinVoigtContact::add_tangent(const ElementState&, int mode, double* dfdq, double* dfdv) const {
    // f = sign (Kc sign (surface - q) - Cc sign v) = Kc (surface - q) - Cc v.
    if (mode != 1) return;
    dfdq[0] -= stiffness_;
    dfdv[0] -= damping_;
}

double KelvinVoigtContact::stored_energy(const ElementState& s, int mode) const {
    if (mode != 1) return 0.0;
    const double d = penetration(s);
    return 0.5 * stiffness_ * d * d;
}

double KelvinVoigtContact::dissipated_power(const ElementState& s, int mode) const {
    if (mode != 1) return 0.0;
    const double r = penetration_rate(s);
    return damping_ * r * r;
}

double KelvinVoigtContact::switching_function(const ElementState& s, int mode) const {
    if (mode == 1) return -force_magnitude(s);
    const double scale = stiffness_ > 0.0 ? stiffness_ : 1.0;
    return std::min(scale * penetration(s), force_magnitude(s));
}

int KelvinVoigtContact::static_mode(const ElementState& s) const {
    const double tol = 1e-12 * std::max(std::abs(surface_), std::abs(s.q[0]));
    return penetration(s) > tol ? 1 : 0;
}

int KelvinVoigtContact::initial_mode(const ElementState& s) const {
    const double d = penetration(s);
    if (d > 0.0 && force_magnitude(s) > 0.0) return 1;
    const double scale = std::max(std::abs(surface_), std::abs(s.q[0]));
    const bool touching = std::abs(d) <= 64.0 * std::numeric_limits<double>::epsilon() * scale;
    return touching && penetration_rate(s) > 0.0 ? 1 : 0;
}

void KelvinVoigtContact::watch_functions(const ElementState& s, int mode, double* g) const {
    g[0] = penetration_rate(s);
    // dF/dt = Kc dd/dt + Cc d2d/dt2, d2d/dt2 = -sign a.
    g[1] = mode == 1 && s.a ? stiffness_ * g[0] - damping_ * sign_ * s.a[0] : 1.0;
}

std::optional<LinearForm> KelvinVoigtContact::linear_form() const {
    return LinearForm{UnilateralSpringDamper{dofs_[0], sign_, surface_, stiffness_, damping_}};
}

ContactReading KelvinVoigtContact::contact_reading(const ElementState& s) const {
    return {penetration(s), force_magnitude(s), s.v[0]};
}

}  // namespace vi
