#include "modal/released_curl.hpp"

#include <cmath>

#include "forces/intrinsic_curvature.hpp"

namespace vi {

std::optional<ReleasedCurl> released_curl(const Case& c, const System& s) {
    const Eigen::VectorXd f = curl_load(c, s);
    if (f.isZero(0.0)) return std::nullopt;
    const Eigen::VectorXd g = expand_to_global(s, solve_static(s, f));
    ReleasedCurl r;
    const int n = s.mesh.node_count();
    for (int node = 0; node < n; ++node) {
        r.x.push_back(s.mesh.x[static_cast<std::size_t>(node)]);
        r.v.push_back(g[global_dof(node, 1)]);
        r.theta.push_back(g[global_dof(node, 2)]);
        if (std::abs(r.v.back()) > std::abs(r.largest)) {
            r.largest = r.v.back();
            r.largest_at = r.x.back() / s.length;
        }
    }
    if (s.right == EndCondition::free) r.tip_lift = r.v.back();
    if (s.left == EndCondition::free && std::abs(r.v.front()) > std::abs(r.tip_lift)) r.tip_lift = r.v.front();
    return r;
}

}  // namespace vi
