#include "model/section_scales.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vi {
namespace {

double bending_modulus(const Case& c, double e, double nu) { return c.material.plate_modulus ? e / (1.0 - nu * nu) : e; }

SectionScale layered(const Case& c, const BeamSection& s, double w) {
    double ea = 0.0, first = 0.0, z = 0.0;
    std::vector<std::pair<const LayerMaterial*, double>> stack;
    for (const Layer& l : s.layers) {
        const auto m = std::find_if(c.materials.begin(), c.materials.end(),
                                    [&](const LayerMaterial& x) { return x.name == l.material; });
        if (m == c.materials.end()) continue;
        const double e = bending_modulus(c, m->youngs_modulus, m->poisson_ratio);
        ea += e * w * l.thickness;
        first += e * w * l.thickness * (z + 0.5 * l.thickness);
        stack.emplace_back(&*m, z);
        z += l.thickness;
    }
    SectionScale out;
    if (!(ea > 0.0)) return out;
    const double axis = first / ea;
    for (std::size_t k = 0; k < stack.size(); ++k) {
        const LayerMaterial& m = *stack[k].first;
        const double bottom = stack[k].second;
        const double t = (k + 1 < stack.size() ? stack[k + 1].second : z) - bottom;
        const double arm = bottom + 0.5 * t - axis;
        out.EI += bending_modulus(c, m.youngs_modulus, m.poisson_ratio) * (w * t * t * t / 12.0 + w * t * arm * arm);
        out.rho_A += m.density * w * t;
    }
    return out;
}

// Solves the 4 x 4 system a x = a[.][4] by Gaussian elimination with partial pivoting; false when
// it is singular (ends that do not hold the beam).
bool solve4(double a[4][5], double x[4]) {
    for (int k = 0; k < 4; ++k) {
        int pivot = k;
        for (int i = k + 1; i < 4; ++i) {
            if (std::abs(a[i][k]) > std::abs(a[pivot][k])) pivot = i;
        }
        if (!(std::abs(a[pivot][k]) > 1e-12 * (1.0 + std::abs(a[k][4])))) return false;
        std::swap(a[k], a[pivot]);
        for (int i = k + 1; i < 4; ++i) {
            const double f = a[i][k] / a[k][k];
            for (int j = k; j < 5; ++j) a[i][j] -= f * a[k][j];
        }
    }
    for (int k = 3; k >= 0; --k) {
        double sum = a[k][4];
        for (int j = k + 1; j < 4; ++j) sum -= a[k][j] * x[j];
        x[k] = sum / a[k][k];
    }
    return true;
}

// Points of the grid over s = x/l on which the static deflection is integrated (midpoint rule for
// the curvature, trapezoids for the slope): the estimate needs a few digits, not more.
constexpr int kGrid = 1000;

// Rayleigh's quotient int EI w''^2 ds / int rho A w^2 ds of the beam of parts (EI and rho A at each
// grid interval's middle) in its own static deflection w under a uniform load, (EI w'')'' = 1 with
// the ends' conditions: the moment M = s^2 / 2 + a + b s, w = c0 + c1 s + the double integral of
// M / EI. 0 when the ends do not hold the beam.
double rayleigh_quotient(const Beam& beam, const std::vector<double>& ei, const std::vector<double>& rho_a) {
    const double h = 1.0 / kGrid;
    // The slope and deflection of the curvatures s^2 / 2, 1 and s over EI, from s = 0.
    std::vector<double> slope[3], deflection[3];
    for (int j = 0; j < 3; ++j) {
        slope[j].assign(kGrid + 1, 0.0);
        deflection[j].assign(kGrid + 1, 0.0);
        for (int k = 0; k < kGrid; ++k) {
            const double m = (k + 0.5) * h;
            const double f = j == 0 ? 0.5 * m * m : j == 1 ? 1.0 : m;
            slope[j][k + 1] = slope[j][k] + h * f / ei[static_cast<std::size_t>(k)];
            deflection[j][k + 1] = deflection[j][k] + 0.5 * h * (slope[j][k] + slope[j][k + 1]);
        }
    }
    double a[4][5] = {};
    int row = 0;
    const auto end = [&](EndCondition e, int k) {
        const double s = k * h;
        const double value[5] = {deflection[1][k], deflection[2][k], 1.0, s, -deflection[0][k]};
        const double turn[5] = {slope[1][k], slope[2][k], 0.0, 1.0, -slope[0][k]};
        const double moment[5] = {1.0, s, 0.0, 0.0, -0.5 * s * s};
        const double shear[5] = {0.0, 1.0, 0.0, 0.0, -s};
        const double* first = e == EndCondition::free ? moment : value;
        const double* second = e == EndCondition::clamped ? turn : e == EndCondition::pinned ? moment : shear;
        std::copy(first, first + 5, a[row++]);
        std::copy(second, second + 5, a[row++]);
    };
    end(beam.left, 0);
    end(beam.right, kGrid);
    double x[4] = {};
    if (!solve4(a, x)) return 0.0;
    double strain = 0.0, kinetic = 0.0;
    for (int k = 0; k < kGrid; ++k) {
        const double m = (k + 0.5) * h;
        const double moment = 0.5 * m * m + x[0] + x[1] * m;
        const auto w = [&](int i) {
            return deflection[0][i] + x[0] * deflection[1][i] + x[1] * deflection[2][i] + x[2] + x[3] * i * h;
        };
        const double mid = 0.5 * (w(k) + w(k + 1));
        strain += h * moment * moment / ei[static_cast<std::size_t>(k)];
        kinetic += h * rho_a[static_cast<std::size_t>(k)] * mid * mid;
    }
    return kinetic > 0.0 ? strain / kinetic : 0.0;
}

}  // namespace

std::vector<SectionScale> section_scales(const Case& c) {
    const Beam& b = c.beam;
    const double e = c.material.effective_modulus();
    if (b.sections.empty()) return {{1.0, e * b.second_moment(), c.material.density * b.area()}};
    std::vector<SectionScale> out;
    for (const BeamSection& s : b.sections) {
        const double w = s.width.value_or(b.width);
        SectionScale p;
        if (s.layers.empty()) {
            const double t = s.thickness.value_or(b.thickness);
            p.EI = e * (w * t * t * t / 12.0);
            p.rho_A = c.material.density * (w * t);
        } else {
            p = layered(c, s, w);
        }
        p.fraction = s.to - s.from;
        out.push_back(p);
    }
    return out;
}

EffectiveBeam effective_beam(const Case& c) {
    const std::vector<SectionScale> parts = section_scales(c);
    EffectiveBeam out;
    if (c.beam.sections.empty()) {
        out.EI = parts.front().EI;
        out.rho_A = parts.front().rho_A;
        out.wave_max = std::sqrt(out.EI / out.rho_A);
        return out;
    }
    // Each grid interval's part; a part without stiffness or mass (a layer naming no material) is
    // reported by the checks and left out here.
    std::vector<double> ei(kGrid, 0.0), rho_a(kGrid, 0.0);
    double compliance = 0.0, mass = 0.0, length = 0.0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const SectionScale& p = parts[i];
        if (!(p.EI > 0.0 && p.rho_A > 0.0 && p.fraction > 0.0)) continue;
        compliance += p.fraction / p.EI;
        mass += p.fraction * p.rho_A;
        length += p.fraction;
        out.wave_max = std::max(out.wave_max, std::sqrt(p.EI / p.rho_A));
    }
    if (!(length > 0.0)) {
        Case plain = c;
        plain.beam.sections.clear();
        return effective_beam(plain);
    }
    // Uniform averages first; then each interval takes the part holding its middle.
    out.EI = length / compliance;
    out.rho_A = mass / length;
    std::size_t part = 0;
    for (int k = 0; k < kGrid; ++k) {
        const double m = (k + 0.5) / kGrid;
        while (part + 1 < parts.size() && m >= c.beam.sections[part + 1].from) ++part;
        const bool usable = parts[part].EI > 0.0 && parts[part].rho_A > 0.0;
        ei[static_cast<std::size_t>(k)] = usable ? parts[part].EI : out.EI;
        rho_a[static_cast<std::size_t>(k)] = usable ? parts[part].rho_A : out.rho_A;
    }
    // Rayleigh's quotient of the beam of parts against the uniform beam's (EI = rho A = 1) in their own
    // static deflections: EI / rho A of the uniform beam with the same first frequency. Kept with its
    // own shape's mean rho A, so that a uniform beam gives back its own values.
    const double beam_quotient = rayleigh_quotient(c.beam, ei, rho_a);
    const double unit_quotient = rayleigh_quotient(c.beam, std::vector<double>(kGrid, 1.0), std::vector<double>(kGrid, 1.0));
    if (beam_quotient > 0.0 && unit_quotient > 0.0) out.EI = out.rho_A * beam_quotient / unit_quotient;
    return out;
}

}  // namespace vi
