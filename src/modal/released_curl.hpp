#pragma once
// The released (curled) shape of a beam at rest: the static shape its curl alone gives it, with no
// support, load or voltage, which `modes` reports beside the modes about the straight reference.

#include <optional>
#include <vector>

#include "fem/system.hpp"
#include "model/case.hpp"

namespace vi {

// The released shape at the nodes of s, and its lift.
struct ReleasedCurl {
    std::vector<double> x;      // node coordinates [m]
    std::vector<double> v;      // transverse displacement there, up positive [m]
    std::vector<double> theta;  // rotation dv/dx there [rad]
    double tip_lift = 0.0;      // v at the free end (the larger of two); 0 with both ends held [m]
    double largest = 0.0;       // the node v of largest magnitude, signed [m]
    double largest_at = 0.0;    // its x/l [-]
};

// The released shape of c on s (built without supports): K q = f_curl, f_curl the [curl] table's
// and the layers' moments (forces/intrinsic_curvature.hpp); nothing when no curl loads the beam (a
// straight beam, or one clamped at both ends). Throws std::runtime_error when K is singular.
std::optional<ReleasedCurl> released_curl(const Case& c, const System& s);

}  // namespace vi
