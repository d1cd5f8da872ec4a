#include "problem/electrode_elements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fem/beam_element.hpp"
#include "fem/gauss_legendre.hpp"

namespace vi {
namespace {

// Hermite shape values of v at xi on an element of length L: (v1, theta1, v2, theta2).
std::array<double, 4> shape_values(double xi, double L) {
    return {hermite_v(xi, L, 1, 0, 0, 0), hermite_v(xi, L, 0, 1, 0, 0), hermite_v(xi, L, 0, 0, 1, 0),
            hermite_v(xi, L, 0, 0, 0, 1)};
}

// The quadrature points of electrode k over the elements it faces, and the DOFs they touch.
struct PadMesh {
    PadGeometry geometry;
    std::vector<int> dofs;
    std::vector<PadPoint> points;
};

PadMesh pad_mesh(const Case& c, std::size_t k, const System& s, const std::vector<int>& bending_position) {
    const Electrode& e = c.electrodes[k];
    PadMesh m;
    PadGeometry& g = m.geometry;
    g.sign = e.side == Side::above ? 1.0 : -1.0;
    g.gap = e.gap;
    g.dielectric_thickness = e.dielectric_thickness;
    g.dielectric_permittivity = e.dielectric_permittivity;
    g.width = e.width > 0.0 ? e.width : c.beam.width;
    g.beam_thickness = c.beam.thickness;
    g.fringing = e.fringing;
    g.from = e.from * s.length;
    g.to = e.to * s.length;
    SpanQuadrature q = span_quadrature(s, bending_position, g.from, g.to);
    m.dofs = std::move(q.dofs);
    m.points = std::move(q.points);
    return m;
}

// Moves the v DOF of the node nearest the span's middle to the front of m.dofs (the contact column
// of the time history reads a contact's first DOF).
void middle_first(PadMesh& m, const System& s) {
    const double mid = 0.5 * (m.geometry.from + m.geometry.to);
    int best = -1;
    double distance = std::numeric_limits<double>::infinity();
    for (const PadPoint& p : m.points) {
        for (int end = 0; end < 2; ++end) {
            const int local = p.local[static_cast<std::size_t>(2 * end)];
            if (local < 0) continue;
            // The element's nodes: p.x lies between them; the nearer node to mid wins.
            const auto node = std::upper_bound(s.mesh.x.begin(), s.mesh.x.end(), p.x) - s.mesh.x.begin() - 1 + end;
            const double d = std::abs(s.mesh.x[static_cast<std::size_t>(node)] - mid);
            if (d < distance) {
                distance = d;
                best = local;
            }
        }
    }
    if (best <= 0) return;
    std::swap(m.dofs[0], m.dofs[static_cast<std::size_t>(best)]);
    for (PadPoint& p : m.points) {
        for (int& l : p.local) {
            if (l == 0) l = best;
            else if (l == best) l = 0;
        }
    }
}

}  // namespace

SpanQuadrature span_quadrature(const System& s, const std::vector<int>& bending_position, double from, double to,
                               int per_piece) {
    const QuadratureRule rule = gauss_legendre(per_piece);
    SpanQuadrature m;
    // The span need not end on nodes: each element's overlap with it gets its own Gauss rule,
    // so the integrand is smooth (a cubic's reciprocal square) on every piece.
    const auto local_of = [&](int node, int comp) {
        const int r = s.reduced_of[static_cast<std::size_t>(global_dof(node, comp))];
        if (r < 0) return -1;
        const int b = bending_position[static_cast<std::size_t>(r)];
        const auto it = std::find(m.dofs.begin(), m.dofs.end(), b);
        if (it != m.dofs.end()) return static_cast<int>(it - m.dofs.begin());
        m.dofs.push_back(b);
        return static_cast<int>(m.dofs.size()) - 1;
    };
    for (int el = 0; el < s.mesh.element_count(); ++el) {
        const double x0 = s.mesh.x[static_cast<std::size_t>(el)], x1 = s.mesh.x[static_cast<std::size_t>(el) + 1];
        const double a = std::max(x0, from), b = std::min(x1, to);
        if (!(b > a)) continue;
        const double L = x1 - x0;
        const std::array<int, 4> local{local_of(el, 1), local_of(el, 2), local_of(el + 1, 1), local_of(el + 1, 2)};
        for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
            PadPoint p;
            p.x = a + (b - a) * rule.nodes[i];
            p.weight = (b - a) * rule.weights[i];
            p.local = local;
            p.shape = shape_values((p.x - x0) / L, L);
            m.points.push_back(p);
        }
    }
    return m;
}

std::vector<std::shared_ptr<const ElectrostaticPad>> electrode_elements(const Case& c, const System& s,
                                                                       const std::vector<int>& bending_position,
                                                                       bool unit_voltage) {
    std::vector<std::shared_ptr<const ElectrostaticPad>> out;
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        const Electrode& e = c.electrodes[k];
        PadMesh m = pad_mesh(c, k, s, bending_position);
        TimeFunction time = unit_voltage ? TimeFunction{} : e.time;
        out.push_back(std::make_shared<const ElectrostaticPad>("electrodes[" + std::to_string(k) + "]", std::move(m.dofs),
                                                               std::move(m.points), m.geometry,
                                                               unit_voltage ? 1.0 : e.voltage, std::move(time)));
    }
    return out;
}

std::vector<std::shared_ptr<const DielectricContact>> dielectric_contacts(const Case& c, const System& s,
                                                                          const std::vector<int>& bending_position) {
    std::vector<std::shared_ptr<const DielectricContact>> out;
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        const Electrode& e = c.electrodes[k];
        if (!(e.dielectric_thickness > 0.0)) continue;
        PadMesh m = pad_mesh(c, k, s, bending_position);
        if (m.dofs.empty()) continue;
        middle_first(m, s);
        const double stiffness = e.dielectric_modulus * m.geometry.width / e.dielectric_thickness;
        std::string name = "electrodes[" + std::to_string(k) + "]";
        name += ".dielectric";
        if (e.work_of_adhesion) {
            // The adhesion energy per unit length of beam lying on the layer: w over the width w_e.
            const AdhesiveLayerLaw law(stiffness, *e.work_of_adhesion * m.geometry.width, e.adhesion_range);
            out.push_back(std::make_shared<const DielectricContact>(std::move(name), std::move(m.dofs),
                                                                    std::move(m.points), m.geometry, law));
            continue;
        }
        out.push_back(std::make_shared<const DielectricContact>(std::move(name), std::move(m.dofs), std::move(m.points),
                                                                m.geometry, stiffness));
    }
    return out;
}

}  // namespace vi
