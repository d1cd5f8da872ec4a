#include "forces/perforated_film.hpp"

#include <cmath>
#include <numbers>

#include "forces/squeeze_film.hpp"

namespace vi {

PerforationCell perforation_cell(const FilmPerforation& p) {
    const double root_pi = std::sqrt(std::numbers::pi);
    return {p.circle ? 0.5 * p.size : p.size / root_pi, p.pitch / root_pi};
}

double skvor_function(double beta) {
    const double b2 = beta * beta;
    return 4.0 * b2 - b2 * b2 - 4.0 * std::log(beta) - 3.0;
}

double hole_resistance(const FilmPerforation& p, double viscosity) {
    const double r0 = perforation_cell(p).hole_radius;
    const double s = p.size;
    // Shah and London's Poiseuille number of a square duct, f Re = 56.91 (hydraulic diameter s).
    const double tube = p.circle ? 8.0 * viscosity * p.plate_thickness / (std::numbers::pi * r0 * r0 * r0 * r0)
                                 : 28.455 * viscosity * p.plate_thickness / (s * s * s * s);
    return tube + 3.0 * viscosity / (r0 * r0 * r0);
}

StripFactor strip_factor(double y) {
    // Below z = 0.2 the closed form loses digits to cancellation; its series to y^6 is exact there
    // (the next term is below 1e-18).
    if (y < 0.04) {
        constexpr double c[7] = {1.0, -1.0 / 10.0, 17.0 / 1680.0, -31.0 / 30240.0, 691.0 / 6652800.0,
                                 -5461.0 / 518918400.0, 929569.0 / 871782912000.0};
        double value = 0.0, slope = 0.0;
        for (int k = 6; k >= 1; --k) {
            value = value * y + c[k];
            slope = slope * y + k * c[k];
        }
        return {value * y + c[0], slope};
    }
    const double z = std::sqrt(y);
    const double t = std::tanh(0.5 * z);
    const double z3 = y * z;
    const double value = 12.0 / y - 24.0 * t / z3;
    const double dz = -24.0 / z3 + 72.0 * t / (y * y) - 12.0 * (1.0 - t * t) / z3;
    return {value, dz / (2.0 * z)};
}

PerforationFactor perforation_factor(const FilmPerforation& p, const FilmGas& gas, double gap, double solid_log_slope) {
    const PerforationCell cell = perforation_cell(p);
    const double beta = cell.hole_radius / cell.cell_radius;
    const double open = beta * beta;
    const double cell_area = p.pitch * p.pitch;
    // a = mu_eff / g^3, the gap's own resistivity; the cell's radial gap flow to its hole is in
    // series with the hole: R = R_hole + k a per cell.
    const double a = gas.viscosity / veijola_factor(gas.mean_free_path / gap) / (gap * gap * gap);
    const double k = 3.0 * skvor_function(beta) / (2.0 * std::numbers::pi * (1.0 - open));
    const double hole = hole_resistance(p, gas.viscosity);
    const double resistance = hole + k * a;
    // Across the strip: (1 / 12 a) P'' - P / (A_c R) = -(1 - open) dh/dt, so z^2 = 12 a w^2 / (A_c R).
    const double y = 12.0 * a * p.width * p.width / (cell_area * resistance);
    const StripFactor f = strip_factor(y);
    const double dy = y * solid_log_slope * hole / resistance;
    return {(1.0 - open) * f.value, (1.0 - open) * f.slope * dy};
}

}  // namespace vi
