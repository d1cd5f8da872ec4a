#pragma once
// Quadrature points of a pad or dielectric contact on one beam element of length L [m]: four
// points at xi = 0.1, 0.4, 0.7, 0.95 with equal weights L/4 and the Hermite shapes of v there.

#include <vector>

#include "forces/electrostatic_pad.hpp"

namespace vi::test {

inline std::vector<PadPoint> one_element_points(double L) {
    std::vector<PadPoint> pts;
    for (double xi : {0.1, 0.4, 0.7, 0.95}) {
        PadPoint p;
        p.x = xi * L;
        p.weight = L / 4;
        p.local = {0, 1, 2, 3};
        p.shape = {1 - 3 * xi * xi + 2 * xi * xi * xi, L * (xi - 2 * xi * xi + xi * xi * xi), 3 * xi * xi - 2 * xi * xi * xi,
                   L * (-xi * xi + xi * xi * xi)};
        pts.push_back(p);
    }
    return pts;
}

}  // namespace vi::test
