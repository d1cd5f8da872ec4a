#include "problem/electrode_elements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fem/beam_element.hpp"
#include "fem/gauss_legendre.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"

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
    g.fringing = e.fringing;
    g.from = e.from * s.length;
    g.to = e.to * s.length;
    const SectionResultants& middle = section_at(s, 0.5 * (g.from + g.to));
    g.width = e.width > 0.0 ? e.width : middle.width;
    g.beam_thickness = middle.thickness;
    SpanQuadrature q = span_quadrature(s, bending_position, g.from, g.to);
    m.dofs = std::move(q.dofs);
    m.points = std::move(q.points);
    // Over sections of other widths, each point's parallel-plate force and layer stiffness scale
    // with the width there; Meijs-Fokkema's fringe is a law of one strip width, so an electrode with
    // fringing must face one width.
    // Release holes take their area out of the electrode's (their own edges' fringe field ignored):
    // the force, the capacitance and the layer's contact all scale with the solid fraction there.
    for (PadPoint& p : m.points) p.weight *= section_at(s, p.x).solid_fraction;
    if (e.width > 0.0 || !s.sectioned) return m;
    for (PadPoint& p : m.points) {
        const double w = section_at(s, p.x).width;
        if (w == g.width) continue;
        if (e.fringing != Fringing::none) {
            throw InputError("electrodes[" + std::to_string(k) + "].fringing: the electrode faces sections of widths " +
                             significant(g.width * 1e6, 4) + " um and " + significant(w * 1e6, 4) +
                             " um; the fringing model is for one strip width: split the electrode at the section boundary");
        }
        p.weight *= w / g.width;
    }
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

namespace {

// The layer of electrode k, or null when it has none or faces no part of the beam that moves.
std::shared_ptr<const DielectricContact> dielectric_contact(const Case& c, std::size_t k, const System& s,
                                                            const std::vector<int>& bending_position) {
    const Electrode& e = c.electrodes[k];
    if (!(e.dielectric_thickness > 0.0)) return nullptr;
    PadMesh m = pad_mesh(c, k, s, bending_position);
    if (m.dofs.empty()) return nullptr;
    middle_first(m, s);
    const double stiffness = e.dielectric_modulus * m.geometry.width / e.dielectric_thickness;
    std::string name = "electrodes[" + std::to_string(k) + "]";
    name += ".dielectric";
    if (e.work_of_adhesion) {
        // The adhesion energy per unit length of beam lying on the layer: w over the width w_e.
        const AdhesiveLayerLaw law(stiffness, *e.work_of_adhesion * m.geometry.width, e.adhesion_range);
        return std::make_shared<const DielectricContact>(std::move(name), std::move(m.dofs), std::move(m.points),
                                                         m.geometry, law);
    }
    return std::make_shared<const DielectricContact>(std::move(name), std::move(m.dofs), std::move(m.points),
                                                     m.geometry, stiffness);
}

class ElectrodePads final : public ElementFamily {
public:
    [[nodiscard]] std::string_view name() const override { return "electrostatic pads"; }
    [[nodiscard]] std::vector<FamilyElement> elements(const ElementSource& src) const override {
        std::vector<FamilyElement> out;
        for (auto& pad : electrode_elements(src.c, src.system, src.bending_position, false)) {
            out.push_back({std::move(pad), {"electrodes", out.size()}});
        }
        return out;
    }
};

class DielectricLayers final : public ElementFamily {
public:
    [[nodiscard]] std::string_view name() const override { return "dielectric layers"; }
    [[nodiscard]] std::vector<FamilyElement> elements(const ElementSource& src) const override {
        std::vector<FamilyElement> out;
        for (std::size_t k = 0; k < src.c.electrodes.size(); ++k) {
            if (auto layer = dielectric_contact(src.c, k, src.system, src.bending_position)) out.push_back({std::move(layer), {"electrodes", k}});
        }
        return out;
    }
};

}  // namespace

const ElementFamily& electrode_pads() {
    static const ElectrodePads family;
    return family;
}

const ElementFamily& dielectric_layers() {
    static const DielectricLayers family;
    return family;
}

}  // namespace vi
