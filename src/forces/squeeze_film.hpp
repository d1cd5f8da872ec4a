#pragma once
// SqueezeFilm: the damping of the gas film squeezed between the beam and a surface along a span,
// narrow-beam incompressible Reynolds solution with Veijola's rarefied-gas viscosity, integrated on
// the beam's Hermite shape functions by Gauss quadrature (docs/squeeze-film.md).

#include <string>
#include <vector>

#include "forces/electrostatic_pad.hpp"
#include "forces/perforated_film.hpp"

namespace vi {

// The gas: dynamic viscosity mu [Pa s] and mean free path lambda [m].
struct FilmGas {
    double viscosity = 0.0;
    double mean_free_path = 0.0;
};

// Where the film is: the surface at `gap` [m] from the beam at rest on one side (sign = +1 above,
// -1 below, as an electrode's), the film's width w [m] across the beam and its span [m].
struct FilmGeometry {
    double sign = -1.0;
    double gap = 0.0;
    double width = 0.0;
    double from = 0.0, to = 0.0;
    // A contact surface at the film's far side (an electrode's dielectric layer, which stops the beam
    // there): the film ends where it begins. Its law is held at kFilmEndGap of the gap below that
    // (and in contact), instead of stopping the run.
    bool ends_on_contact = false;
};

// Where a film on a contact surface ends, as a fraction of its gap at rest, and where a film without
// one stops the run: the gap law c ~ mu_eff w^3 / g^3 grows without bound as g closes (still like
// g^-1.84 with Veijola's slip), so a beam driven onto the surface would never land and the
// integrator would creep toward it. At 1e-3 of the gap (1.8 nm for the capacitive example's 1.8 um of
// air) the gap is at the scale of deposited and plated surfaces' roughness, a few nm RMS, whose
// asperities touch before the mean planes meet: below it the continuum film with slip has no meaning.
inline constexpr double kFilmEndGap = 1e-3;

// Gauss-Legendre points per beam element (or part of one) a film integrates with: half the pad's,
// since the film's cost is its Veijola power at every point; exact for a uniform gap (degree 7),
// and against 8 points the switch example's closing time moves by 1.6e-7 and its first peak force by
// 2e-6, the level of its CVODE tolerance (docs/squeeze-film.md §2).
inline constexpr int kFilmGaussPoints = 4;

// Veijola's rarefaction factor Q(Kn) = 1 + 9.638 Kn^1.159 (mu_eff = mu / Q), fitted for
// 0 <= Kn <= 880: T. Veijola et al., Sensors and Actuators A 48 (1995) 239-248.
double veijola_factor(double knudsen);
inline constexpr double kVeijolaKnudsenMax = 880.0;

// Damping per unit length c(g) = mu_eff(g) w^3 / g^3 [N s/m^2] of a film of width w at gap g, and
// dc/dg [N s/m^3] (mu_eff depends on g through Kn = lambda / g).
struct FilmCoefficient {
    double c = 0.0, dc = 0.0;
};
FilmCoefficient film_coefficient(const FilmGas& gas, double width, double gap);

// Finite-length factor beta(w/L) of a rigid rectangular plate's incompressible damping, c = beta mu
// w^3 L / g^3 (w <= L; the gas escapes at all four edges): beta = 1 - (192/pi^5) (w/L) sum over odd n
// of tanh(n pi L / (2 w)) / n^5 (J. J. Blech, J. Lubrication Technol. 105 (1983) 615-620; M. Bao, Analysis and Design
// Principles of MEMS Devices, Elsevier 2005, ch. 3), about 1 - 0.63 w/L for w << L.
// The element itself is the narrow-beam limit beta = 1 (docs/squeeze-film.md §2).
double rectangular_plate_factor(double width_over_length);

// Squeeze number sigma = 12 mu_eff w^2 omega / (p g^2) [-] at circular frequency omega [rad/s] and
// ambient pressure p [Pa]: above about 0.3 the film's spring force is no longer small beside its
// damping (docs/squeeze-film.md §3).
double squeeze_number(const FilmGas& gas, double width, double gap, double omega, double pressure);
inline constexpr double kSqueezeNumberLimit = 0.3;

// The film. Line force on the beam -c(g(x)) dv/dt(x), with the local gap g = gap - sign v(x) (and,
// under release holes, c the perforated strip's: perforation_factor): a
// damper only (stored energy 0, input power 0, dissipated power int c (dv/dt)^2 dx >= 0), nonlinear
// in the gap as the beam closes it.
class SqueezeFilm final : public ForceElement {
public:
    // `holes`: per point, the perforation of the plate there (size 0: solid); empty: solid everywhere.
    SqueezeFilm(std::string name, std::vector<int> dofs, std::vector<PadPoint> points, FilmGeometry geometry,
                FilmGas gas, std::vector<FilmPerforation> holes = {});

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] std::string kind() const override { return "squeeze film"; }
    [[nodiscard]] const std::vector<int>& dofs() const override { return dofs_; }

    void add_force(const ElementState& s, int mode, double* f) const override;
    void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const override;
    [[nodiscard]] double stored_energy(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double dissipated_power(const ElementState& s, int mode) const override;
    double add_force_and_power(const ElementState& s, int mode, double* f) const override;
    [[nodiscard]] DissipationKind dissipation_kind() const override { return DissipationKind::film; }
    [[nodiscard]] double input_power(const ElementState&, int) const override { return 0.0; }
    [[nodiscard]] double position() const override { return 0.5 * (geometry_.from + geometry_.to); }
    // Constant, linear and quadratic line loads over the span (the film's force follows the velocity).
    [[nodiscard]] std::vector<std::vector<double>> load_patterns() const override;

    [[nodiscard]] const FilmGeometry& geometry() const { return geometry_; }
    [[nodiscard]] const FilmGas& gas() const { return gas_; }

private:
    // The film's coefficient at p: at the local gap, or at kFilmEndGap of the gap where the gap is
    // below that and the film ends on a contact surface (dc then 0); throws std::domain_error there
    // for a film without one (the film has no finite force at contact: a support must stop the beam).
    [[nodiscard]] FilmCoefficient coefficient(const PadPoint& p, const double* q) const;
    // The solid strip's coefficient at gap g, times the holes' factor at point k.
    [[nodiscard]] FilmCoefficient perforated(std::size_t k, double g) const;

    std::string name_;
    std::vector<int> dofs_;
    std::vector<PadPoint> points_;
    FilmGeometry geometry_;
    FilmGas gas_;
    std::vector<FilmPerforation> holes_;
};

}  // namespace vi
