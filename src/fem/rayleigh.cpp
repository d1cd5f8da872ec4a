#include "fem/rayleigh.hpp"

#include <cmath>
#include <stdexcept>

namespace vi {

RayleighCoefficients rayleigh_from_ratios(double w1, double xi1, double w2, double xi2) {
    const double det = w2 * w2 - w1 * w1;
    if (!(w1 > 0.0 && w2 > 0.0) || std::abs(det) <= 1e-12 * w2 * w2) {
        throw std::invalid_argument("Rayleigh damping needs two distinct positive frequencies");
    }
    RayleighCoefficients c;
    c.beta = 2.0 * (w2 * xi2 - w1 * xi1) / det;
    c.alpha = 2.0 * w1 * xi1 - c.beta * w1 * w1;
    return c;
}

double rayleigh_ratio(const RayleighCoefficients& c, double w) { return 0.5 * (c.alpha / w + c.beta * w); }

}  // namespace vi
