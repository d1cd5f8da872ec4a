#include "dynamics/electrode_elements.hpp"

#include <algorithm>
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

}  // namespace

std::vector<std::shared_ptr<const ElectrostaticPad>> electrode_elements(const Case& c, const System& s,
                                                                       const std::vector<int>& bending_position,
                                                                       bool unit_voltage) {
    const QuadratureRule rule = gauss_legendre(kPadGaussPoints);
    std::vector<std::shared_ptr<const ElectrostaticPad>> out;
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        const Electrode& e = c.electrodes[k];
        PadGeometry g;
        g.sign = e.side == Side::above ? 1.0 : -1.0;
        g.gap = e.gap;
        g.dielectric_thickness = e.dielectric_thickness;
        g.dielectric_permittivity = e.dielectric_permittivity;
        g.width = e.width > 0.0 ? e.width : c.beam.width;
        g.beam_thickness = c.beam.thickness;
        g.fringing = e.fringing;
        g.from = e.from * s.length;
        g.to = e.to * s.length;
        // The span need not end on nodes: each element's overlap with it gets its own Gauss rule,
        // so the integrand is smooth (a cubic's reciprocal square) on every piece.
        std::vector<int> dofs;
        std::vector<PadPoint> points;
        const auto local_of = [&](int node, int comp) {
            const int r = s.reduced_of[static_cast<std::size_t>(global_dof(node, comp))];
            if (r < 0) return -1;
            const int b = bending_position[static_cast<std::size_t>(r)];
            const auto it = std::find(dofs.begin(), dofs.end(), b);
            if (it != dofs.end()) return static_cast<int>(it - dofs.begin());
            dofs.push_back(b);
            return static_cast<int>(dofs.size()) - 1;
        };
        for (int el = 0; el < s.mesh.element_count(); ++el) {
            const double x0 = s.mesh.x[static_cast<std::size_t>(el)], x1 = s.mesh.x[static_cast<std::size_t>(el) + 1];
            const double a = std::max(x0, g.from), b = std::min(x1, g.to);
            if (!(b > a)) continue;
            const double L = x1 - x0;
            const std::array<int, 4> local{local_of(el, 1), local_of(el, 2), local_of(el + 1, 1), local_of(el + 1, 2)};
            for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
                PadPoint p;
                p.x = a + (b - a) * rule.nodes[i];
                p.weight = (b - a) * rule.weights[i];
                p.local = local;
                p.shape = shape_values((p.x - x0) / L, L);
                points.push_back(p);
            }
        }
        TimeFunction time = unit_voltage ? TimeFunction{} : e.time;
        out.push_back(std::make_shared<const ElectrostaticPad>("electrodes[" + std::to_string(k) + "]", std::move(dofs),
                                                               std::move(points), g, unit_voltage ? 1.0 : e.voltage,
                                                               std::move(time)));
    }
    return out;
}

}  // namespace vi
