#include "modal/shape_sampling.hpp"

#include <algorithm>

#include "fem/beam_element.hpp"

namespace vi {

SampledShape sample_shape(const System& s, const Eigen::VectorXd& g, int per_element) {
    per_element = std::max(1, per_element);
    SampledShape out;
    const Mesh& mesh = s.mesh;
    for (int e = 0; e < mesh.element_count(); ++e) {
        const double L = mesh.element_length(e);
        const double v1 = g[global_dof(e, 1)], t1 = g[global_dof(e, 2)];
        const double v2 = g[global_dof(e + 1, 1)], t2 = g[global_dof(e + 1, 2)];
        const int first = e == 0 ? 0 : 1;
        for (int k = first; k <= per_element; ++k) {
            const double xi = static_cast<double>(k) / per_element;
            out.x.push_back(k == per_element ? mesh.x[e + 1] : mesh.x[e] + xi * L);
            out.v.push_back(hermite_v(xi, L, v1, t1, v2, t2));
            out.theta.push_back(hermite_slope(xi, L, v1, t1, v2, t2));
        }
    }
    return out;
}

}  // namespace vi
