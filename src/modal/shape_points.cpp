#include "modal/shape_points.hpp"

#include <algorithm>
#include <cmath>

#include "fem/beam_element.hpp"
#include "model/bisection.hpp"

namespace vi {
namespace {

double poly(const Eigen::Vector4d& c, double t) { return c[0] + t * (c[1] + t * (c[2] + t * c[3])); }

Eigen::Vector4d derivative(const Eigen::Vector4d& c) { return {c[1], 2 * c[2], 3 * c[3], 0.0}; }

// Real roots of a polynomial of degree <= 2 (coefficients c0, c1, c2), any order.
std::vector<double> quadratic_roots(double c0, double c1, double c2) {
    const double scale = std::max({std::abs(c0), std::abs(c1), std::abs(c2)});
    if (scale == 0.0) return {};
    if (std::abs(c2) <= 1e-14 * scale) {
        if (std::abs(c1) <= 1e-14 * scale) return {};
        return {-c0 / c1};
    }
    const double disc = c1 * c1 - 4 * c2 * c0;
    if (disc < 0) return {};
    // Numerically stable pair: q = -(c1 + sign(c1) sqrt(disc)) / 2.
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    std::vector<double> r;
    if (q != 0.0) r.push_back(c0 / q);
    r.push_back(q / c2);
    return r;
}

// Root of a polynomial monotone on [a, b] with a sign change, by bisection to machine precision.
double bisect(const Eigen::Vector4d& c, double a, double b) {
    return bisect_sign_change([&](double x) { return poly(c, x); }, a, b);
}

// Per element: polynomial of v (or theta, scaled to the same x) in xi.
struct PiecewisePoly {
    std::vector<Eigen::Vector4d> coeffs;  // in xi, one per element
    std::vector<double> node_values;      // exact values at the nodes (the DOFs themselves)
};

struct EndFlags {
    bool v_fixed_left, v_fixed_right, t_fixed_left, t_fixed_right;
};

// One-sided derivative signs and second derivative decide whether x is a local max of |f|.
void collect_peaks(const System& s, const PiecewisePoly& f, bool fixed_left, bool fixed_right, double scale,
                   std::vector<ShapePeak>& out) {
    const Mesh& mesh = s.mesh;
    const int ne = mesh.element_count();
    const double l = s.length;
    std::vector<double> xs;
    auto add = [&](double x, double value) {
        if (value == 0.0) return;
        const double xl = x / l;
        if (!out.empty() && std::abs(out.back().x - xl) <= 1e-9) return;
        out.push_back({xl, std::abs(value) * scale});
    };
    for (int e = 0; e < ne; ++e) {
        const Eigen::Vector4d& c = f.coeffs[e];
        const Eigen::Vector4d d1 = derivative(c);
        const double f_end = f.node_values[static_cast<std::size_t>(e) + 1];
        const Eigen::Vector4d d2 = derivative(d1);
        const double L = mesh.element_length(e);
        // Left node of this element (a kink of a piecewise polynomial can be a peak).
        const double f0 = f.node_values[static_cast<std::size_t>(e)];
        const double right_slope = d1[0];
        if (e == 0) {
            if (!fixed_left && f0 * right_slope < 0) add(mesh.x[0], f0);
        } else {
            const double left_slope = poly(derivative(f.coeffs[e - 1]), 1.0) / mesh.element_length(e - 1);
            if (f0 * left_slope > 0 && f0 * right_slope / L < 0) add(mesh.x[e], f0);
        }
        std::vector<double> crit = quadratic_roots(d1[0], d1[1], d1[2]);
        std::sort(crit.begin(), crit.end());
        for (double t : crit) {
            if (!(t > 0.0 && t < 1.0)) continue;
            const double v = poly(c, t);
            if (v * poly(d2, t) < 0) add(mesh.x[e] + t * L, v);
        }
        if (e == ne - 1) {
            if (!fixed_right && f_end * poly(d1, 1.0) > 0) add(mesh.x[e + 1], f_end);
        }
    }
}

void collect_zeros(const System& s, const PiecewisePoly& f, bool fixed_left, bool fixed_right,
                   std::vector<double>& out) {
    const Mesh& mesh = s.mesh;
    const int ne = mesh.element_count();
    const double l = s.length;
    const double end_tol = 1e-9;
    for (int e = 0; e < ne; ++e) {
        const std::size_t k = static_cast<std::size_t>(e);
        for (double t : cubic_roots_in(f.coeffs[e], 0.0, 1.0, f.node_values[k], f.node_values[k + 1])) {
            const double xl = (mesh.x[e] + t * mesh.element_length(e)) / l;
            if (fixed_left && xl <= end_tol) continue;
            if (fixed_right && xl >= 1.0 - end_tol) continue;
            // A zero at a node shows up at the end of one element and the start of the next.
            if (!out.empty() && std::abs(out.back() - xl) <= 1e-12) continue;
            out.push_back(xl);
        }
    }
}

}  // namespace

std::vector<double> cubic_roots_in(const Eigen::Vector4d& c, double lo, double hi) {
    return cubic_roots_in(c, lo, hi, poly(c, lo), poly(c, hi));
}

std::vector<double> cubic_roots_in(const Eigen::Vector4d& c, double lo, double hi, double f_lo, double f_hi) {
    // Split [lo, hi] at the critical points; on each monotone piece a sign change brackets one root.
    std::vector<double> cuts{lo};
    std::vector<double> crit = quadratic_roots(c[1], 2 * c[2], 3 * c[3]);
    std::sort(crit.begin(), crit.end());
    for (double t : crit) {
        if (t > lo && t < hi) cuts.push_back(t);
    }
    cuts.push_back(hi);
    std::vector<double> roots;
    if (f_lo == 0.0) roots.push_back(lo);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double a = cuts[i];
        const double b = cuts[i + 1];
        const double fa = i == 0 ? f_lo : poly(c, a);
        const double fb = i + 2 == cuts.size() ? f_hi : poly(c, b);
        if (fb == 0.0) {
            roots.push_back(b);
        } else if (fa != 0.0 && (fa < 0) != (fb < 0)) {
            roots.push_back(bisect(c, a, b));
        }
    }
    return roots;
}

ShapeFeatures shape_features(const System& s, const Eigen::VectorXd& g) {
    const Mesh& mesh = s.mesh;
    const int ne = mesh.element_count();
    PiecewisePoly v;
    PiecewisePoly theta;
    for (int e = 0; e < ne; ++e) {
        const double L = mesh.element_length(e);
        const Eigen::Vector4d c = hermite_v_coefficients(L, g[global_dof(e, 1)], g[global_dof(e, 2)],
                                                         g[global_dof(e + 1, 1)], g[global_dof(e + 1, 2)]);
        v.coeffs.push_back(c);
        theta.coeffs.push_back(derivative(c) / L);
    }
    for (int node = 0; node < mesh.node_count(); ++node) {
        v.node_values.push_back(g[global_dof(node, 1)]);
        theta.node_values.push_back(g[global_dof(node, 2)]);
    }
    // Only the end conditions exclude points: a pinned support at an end is still a nodal point.
    const EndFlags ends{s.left != EndCondition::free, s.right != EndCondition::free,
                        s.left == EndCondition::clamped, s.right == EndCondition::clamped};

    const double mass_scale = std::sqrt(beam_mass(s));
    ShapeFeatures out;
    collect_zeros(s, v, ends.v_fixed_left, ends.v_fixed_right, out.nodes);
    collect_zeros(s, theta, ends.t_fixed_left, ends.t_fixed_right, out.rotation_nodes);
    collect_peaks(s, v, ends.v_fixed_left, ends.v_fixed_right, mass_scale, out.peaks);
    collect_peaks(s, theta, ends.t_fixed_left, ends.t_fixed_right, s.length * mass_scale, out.rotation_peaks);
    return out;
}

}  // namespace vi
