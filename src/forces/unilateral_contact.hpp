#pragma once
// UnilateralContact: a support (motion limiter) as a two-mode Kelvin-Voigt contact on the transverse
// DOF of its node, open or closed, with an optional pull-off force; the plain contact
// (KelvinVoigtContact) and the adhesive one (AdhesiveContact) are its two kinds (docs/model.md §11,
// docs/adhesion.md §3).

#include <string>
#include <vector>

#include "forces/point_contact.hpp"

namespace vi {

// Surface at height `surface` [m] on side `sign` (+1 below the beam, -1 above), stiffness Kc [N/m],
// damping Cc [N s/m], at x [m] along the beam. Penetration d = sign (surface - v), closed force
// F = Kc d + Cc dd/dt, pushing the beam by sign F. Mode 0: open; mode 1: closed.
// A closed contact opens when F falls below -F_po (F_po = 0: no tension, it opens when F falls through
// 0, which for a damped contact comes while d > 0); an open one closes when d > d_po = -F_po / Kc and
// F > -F_po both hold. What an open contact does (nothing, or an adhesive's attraction) is the kind's.
class UnilateralContact : public PointContact {
public:

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const override;
    // Closed: Cc (dd/dt)^2 [W]; open: 0.
    [[nodiscard]] double dissipated_power(const ElementState& s, int mode) const override;

    // Open: min(s (d - d_po), F + F_po) with s = Kc (1 when Kc = 0), so that it crosses zero upward
    // exactly when both become positive; closed: -(F + F_po).
    [[nodiscard]] double switching_function(const ElementState& s, int mode) const override;
    // Closed where d > d_po (statically F = Kc d); a relative 1e-12 of the lengths in play counts as
    // touching, not penetrating.
    [[nodiscard]] int static_mode(const ElementState& s) const override;
    // Closed where d > d_po and F > -F_po, and where it touches (d = d_po to roundoff) and moves in.
    [[nodiscard]] int initial_mode(const ElementState& s) const override;

    // 0: dd/dt; 1: dF/dt while closed, 1 while open (PointContact).
    void watch_functions(const ElementState& s, int mode, double* g) const override;

    // d, the closed force F (negative while an adhesive contact pulls) and the point's velocity.
    [[nodiscard]] ContactReading contact_reading(const ElementState& s) const override;
    // F = Kc d + Cc dd/dt [N], whether or not the contact is closed.
    [[nodiscard]] double force_magnitude(const ElementState& s) const {
        return stiffness_ * penetration(s) + damping_ * penetration_rate(s);
    }
    // F_po [N]: 0 for a plain contact.
    [[nodiscard]] double pull_off_force() const { return pull_off_; }
    [[nodiscard]] double stiffness() const { return stiffness_; }  // Kc [N/m]
    [[nodiscard]] double damping() const { return damping_; }      // Cc [N s/m]

protected:
    // Throws std::invalid_argument naming the contact when the data shared by both kinds are not
    // consistent (a DOF, a side, finite lengths, Kc and Cc >= 0).
    UnilateralContact(std::string name, int dof, double sign, double surface, double stiffness, double damping,
                      double x, double pull_off);

    // What the open contact adds to the force and to df/dq (nothing for a plain contact).
    virtual void add_open_force(const ElementState& /*s*/, double* /*f*/) const {}
    virtual void add_open_tangent(const ElementState& /*s*/, double* /*dfdq*/) const {}

    double stiffness_, damping_;
    double pull_off_;  // F_po [N]
    double d_po_;      // where an open contact closes, -F_po / Kc [m] (0 without pull-off)
};

}  // namespace vi
