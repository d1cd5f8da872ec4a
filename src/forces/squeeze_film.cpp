#include "forces/squeeze_film.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace vi {

namespace {

// Veijola et al. (1995), eq. for the effective viscosity: Q = 1 + kA Kn^kB.
constexpr double kA = 9.638;
constexpr double kB = 1.159;

}  // namespace

double veijola_factor(double knudsen) { return 1.0 + kA * std::pow(knudsen, kB); }

FilmCoefficient film_coefficient(const FilmGas& gas, double width, double gap) {
    const double kn = gas.mean_free_path / gap;
    const double slip = kA * std::pow(kn, kB);
    const double inverse = 1.0 / gap;
    const double w_over_g = width * inverse;
    FilmCoefficient out;
    out.c = gas.viscosity / (1.0 + slip) * w_over_g * w_over_g * w_over_g;
    // d ln c / d ln g = kB slip / (1 + slip) - 3 (Kn ~ 1/g lowers the slip as the gap closes).
    out.dc = out.c * inverse * (kB * slip / (1.0 + slip) - 3.0);
    return out;
}

double rectangular_plate_factor(double width_over_length) {
    const double eta = width_over_length;
    double sum = 0.0;
    // Terms fall as 1/n^5: up to n = 99 the rest is below 1e-9 of the sum.
    for (int n = 1; n < 100; n += 2) {
        const double dn = n;
        sum += std::tanh(dn * std::numbers::pi / (2.0 * eta)) / (dn * dn * dn * dn * dn);
    }
    return 1.0 - 192.0 * eta / std::pow(std::numbers::pi, 5) * sum;
}

double squeeze_number(const FilmGas& gas, double width, double gap, double omega, double pressure) {
    const double mu_eff = gas.viscosity / veijola_factor(gas.mean_free_path / gap);
    return 12.0 * mu_eff * width * width * omega / (pressure * gap * gap);
}

SqueezeFilm::SqueezeFilm(std::string name, std::vector<int> dofs, std::vector<PadPoint> points, FilmGeometry geometry,
                         FilmGas gas, std::vector<FilmPerforation> holes)
    : name_(std::move(name)), dofs_(std::move(dofs)), points_(std::move(points)), geometry_(geometry), gas_(gas),
      holes_(std::move(holes)) {
    const FilmGeometry& g = geometry_;
    if (points_.empty() || std::abs(g.sign) != 1.0 || !(g.gap > 0.0) || !(g.width > 0.0) || !(gas_.viscosity > 0.0) ||
        !(gas_.mean_free_path > 0.0)) {
        throw std::invalid_argument(name_ + ": inconsistent squeeze film data");
    }
    if (!holes_.empty() && holes_.size() != points_.size()) throw std::invalid_argument(name_ + ": one perforation per point");
    for (const FilmPerforation& h : holes_) {
        if (h.size > 0.0 && !(h.size < h.pitch && h.plate_thickness > 0.0 && h.width > 0.0)) {
            throw std::invalid_argument(name_ + ": inconsistent perforation data");
        }
    }
    for (const PadPoint& p : points_) {
        for (int l : p.local) {
            if (l >= static_cast<int>(dofs_.size())) throw std::invalid_argument(name_ + ": DOF index out of range");
        }
    }
}

FilmCoefficient SqueezeFilm::coefficient(const PadPoint& p, const double* q) const {
    const double g = geometry_.gap - geometry_.sign * point_displacement(p, q);
    const double end = kFilmEndGap * geometry_.gap;
    const auto k = static_cast<std::size_t>(&p - points_.data());
    if (g > end) return perforated(k, g);
    if (geometry_.ends_on_contact) return {perforated(k, end).c, 0.0};
    char buf[200];
    std::snprintf(buf, sizeof buf, "the beam closes the film to %.3g nm at x = %.4g um (gap at rest %.3g um)", g * 1e9,
                  p.x * 1e6, geometry_.gap * 1e6);
    std::string message = name_;
    message.append(": ").append(buf).append(
        "; the film has no finite force at contact: a support must stop the beam before the surface "
        "(docs/squeeze-film.md)");
    throw std::domain_error(message);
}

FilmCoefficient SqueezeFilm::perforated(std::size_t k, double g) const {
    FilmCoefficient c = film_coefficient(gas_, geometry_.width, g);
    if (holes_.empty() || !(holes_[k].size > 0.0)) return c;
    const PerforationFactor f = perforation_factor(holes_[k], gas_, g, c.dc / c.c);
    c.dc = c.dc * f.value + c.c * f.slope;
    c.c *= f.value;
    return c;
}

void SqueezeFilm::add_force(const ElementState& s, int mode, double* f) const {
    static_cast<void>(add_force_and_power(s, mode, f));
}

double SqueezeFilm::add_force_and_power(const ElementState& s, int, double* f) const {
    double power = 0.0;
    for (const PadPoint& p : points_) {
        const double c = coefficient(p, s.q).c;
        const double rate = point_displacement(p, s.v);
        add_point_load(p, -c * rate * p.weight, f);
        power += c * rate * rate * p.weight;
    }
    return power;
}

void SqueezeFilm::add_tangent(const ElementState& s, int, double* dfdq, double* dfdv) const {
    const std::size_t n = dofs_.size();
    for (const PadPoint& p : points_) {
        const FilmCoefficient k = coefficient(p, s.q);
        // Line force -c(g) v', g = gap - sign v: d/dv' = -c; d/dv = sign c'(g) v'.
        add_point_stiffness(p, -k.c * p.weight, n, dfdv);
        add_point_stiffness(p, geometry_.sign * k.dc * point_displacement(p, s.v) * p.weight, n, dfdq);
    }
}

double SqueezeFilm::dissipated_power(const ElementState& s, int) const {
    double power = 0.0;
    for (const PadPoint& p : points_) {
        const double rate = point_displacement(p, s.v);
        power += coefficient(p, s.q).c * rate * rate * p.weight;
    }
    return power;
}

std::vector<std::vector<double>> SqueezeFilm::load_patterns() const {
    return line_load_patterns(points_, geometry_.from, geometry_.to, dofs_.size());
}

}  // namespace vi
