#pragma once
// HertzContact: a support as a Hertz sphere-on-flat contact (a dimple of radius R against the beam),
// F = k d^(3/2) with Hunt-Crossley damping, unilateral; its family, which makes one for every
// [[supports]] entry with law = "hertz", and that law's case keys (docs/hertz-contact.md).

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "forces/element_family.hpp"
#include "forces/point_contact.hpp"

namespace vi {

// k = (4/3) E* sqrt(R) [N/m^(3/2)] of a sphere of radius R [m] on a flat, E* [Pa] the effective
// modulus (Johnson, Contact Mechanics, 1985, eq. 4.22).
double hertz_stiffness(double effective_modulus, double radius);
// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [Pa].
double effective_modulus(double e1, double nu1, double e2, double nu2);

// The coefficient of restitution of a point mass that meets the Hunt-Crossley law
// F = k d^(3/2) (1 + alpha dd/dt) at speed v_in: it depends on a = alpha v_in alone (the impact in
// the units d* = (m v_in^2 / k)^(2/5), t* = d* / v_in is x'' = -x^(3/2) (1 + a x'), x(0) = 0,
// x'(0) = 1, and e = -x' where x returns to 0). Integrated by RK4 in steps of 1e-3 t* (error below
// 1e-10 against the undamped closed form), at most 10^7 steps: beyond, std::runtime_error.
double hunt_crossley_restitution(double a);
// alpha [s/m] for which the impact at speed v [m/s] has restitution e in (0, 1]: the a of
// hunt_crossley_restitution(a) = e, found by bisection on [0, 1/e] (e(a) < 1/a for every a, since
// the force never pulls), divided by v.
double hunt_crossley_damping(double restitution, double speed);

// The electrical resistance of a closed contact of radius a (docs/hertz-contact.md §4): Holm's
// constriction rho / (2a) of a circular spot between two bodies of resistivity rho (Holm, Electric
// Contacts, 1967, §4), with Wexler's interpolation to Sharvin's ballistic term where a mean free path
// lambda is given, R = 4 rho lambda / (3 pi a^2) + Gamma(lambda / a) rho / (2a) (Sharvin, Sov. Phys.
// JETP 21 (1965) 655; Wexler, Proc. Phys. Soc. 89 (1966) 927), Gamma(K) = (1 + 0.83 K) / (1 + 1.33 K)
// (Mikrajuddin et al., Mater. Sci. Semicond. Process. 2 (1999) 321), plus a film's
// sigma_f / (pi a^2). The radius is the elastic one, sqrt(R d), or with a hardness H the fully plastic
// sqrt(F / (pi H)) where that is larger (the mean pressure has reached H).
struct ContactResistance {
    double resistivity = 0.0;       // rho [ohm m], > 0
    double film_resistivity = 0.0;  // sigma_f [ohm m^2], >= 0
    double hardness = 0.0;          // H [Pa]; 0: the elastic radius alone
    double mean_free_path = 0.0;    // lambda [m]; 0: Holm's term alone
    double r_on = std::numeric_limits<double>::quiet_NaN();  // the on threshold [ohm]; NaN: none
    // R [ohm] of a spot of radius a [m] (+inf for a <= 0).
    [[nodiscard]] double of_radius(double a) const;
};

// Surface at height `surface` [m] on side `sign` (+1 below the beam, -1 above) at x [m]; the
// beam's DOF `dof` penetrates it by d = sign (surface - q). Closed: F = k d^(3/2) (1 + alpha dd/dt)
// (d^(3/2) taken as 0 where d < 0), pushing the beam by sign F. Mode 0: open, mode 1: closed; it
// closes where d > 0 and 1 + alpha dd/dt > 0 both hold, and opens where either falls through 0
// (F then falls through 0: no tension).
class HertzContact final : public PointContact {
public:
    // k > 0 [N/m^(3/2)], alpha >= 0 [s/m], radius > 0 [m] (the dimple's R); with a resistance model
    // where one is given, and the softer body's yield strength Y [Pa] (NaN: none).
    HertzContact(std::string name, int dof, double sign, double surface, double x, double k, double alpha,
                 double radius, std::optional<ContactResistance> resistance = std::nullopt,
                 double yield_strength = std::numeric_limits<double>::quiet_NaN());

    [[nodiscard]] std::string kind() const override { return "Hertz contact"; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const override;
    // Closed: (2/5) k d^(5/2) [J]; open: 0.
    [[nodiscard]] double stored_energy(const ElementState& s, int mode) const override;
    // Closed: k alpha d^(3/2) (dd/dt)^2 [W]; open: 0.
    [[nodiscard]] double dissipated_power(const ElementState& s, int mode) const override;

    // Open: min(d / R, 1 + alpha dd/dt); closed: minus that.
    [[nodiscard]] double switching_function(const ElementState& s, int mode) const override;
    [[nodiscard]] int static_mode(const ElementState& s) const override;
    [[nodiscard]] int initial_mode(const ElementState& s) const override;

    // 0: dd/dt; 1: dF/dt while closed, 1 while open (PointContact).
    void watch_functions(const ElementState& s, int mode, double* g) const override;
    // Open: min(d / R, 1 + alpha dd/dt), both linear; closed: nullopt.
    [[nodiscard]] std::optional<FreeMode> free_mode(int mode) const override;

    [[nodiscard]] ContactReading contact_reading(const ElementState& s) const override;
    // With a resistance model: R of the spot at penetration d (+inf for d <= 0); else NaN.
    [[nodiscard]] double contact_resistance(const ElementState& s) const override;
    [[nodiscard]] double on_resistance() const override;
    // Hertz's p0 = 3 F / (2 pi a^2) = 3 k d^(1/2) / (2 pi R) of the elastic F = k d^(3/2) over the
    // elastic radius a = sqrt(R d) [Pa] (Johnson, Contact Mechanics, 1985, eq. 4.21); 0 for d <= 0.
    [[nodiscard]] double contact_pressure(double d) const override;
    // 1.6 Y: first yield below the surface of a sphere pressed on a flat (von Mises, nu = 0.3; Johnson,
    // Contact Mechanics, 1985, §6.2, eq. 6.9) [Pa]; NaN without Y.
    [[nodiscard]] double yield_onset_pressure() const override { return 1.6 * yield_strength_; }
    // The contact radius a [m] at penetration d [m]: sqrt(R d), or the plastic one where larger.
    [[nodiscard]] double contact_radius(double d) const;

    // F = k d^(3/2) (1 + alpha dd/dt) [N], whether or not the contact is closed.
    [[nodiscard]] double force_magnitude(const ElementState& s) const;
    [[nodiscard]] double stiffness() const { return k_; }  // k [N/m^(3/2)]
    [[nodiscard]] double alpha() const { return alpha_; }  // [s/m]

private:
    double k_, alpha_, radius_;
    std::optional<ContactResistance> resistance_;
    double yield_strength_;
};

// The family: one HertzContact per [[supports]] entry with law = "hertz"; it registers that option
// of [[supports]]' `law` and the Hertz law's keys.
const ElementFamily& hertz_contacts();

}  // namespace vi
