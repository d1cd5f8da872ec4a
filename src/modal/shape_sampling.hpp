#pragma once
// Samples a mode shape along the beam from the elements' Hermite interpolation, for CSV and plots.

#include <Eigen/Dense>
#include <vector>

#include "fem/system.hpp"

namespace vi {

// v [m-per-shape-unit] and theta [rad-per-shape-unit] at points x (ascending) [m].
struct SampledShape {
    std::vector<double> x;
    std::vector<double> v;
    std::vector<double> theta;
};

// Samples each element at `per_element` equal sub-intervals (nodes included once).
SampledShape sample_shape(const System& s, const Eigen::VectorXd& global_shape, int per_element);

}  // namespace vi
