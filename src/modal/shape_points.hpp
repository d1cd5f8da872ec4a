#pragma once
// Nodal points and peaks of a mode shape, found inside elements from their Hermite interpolation.

#include <Eigen/Dense>
#include <vector>

#include "fem/system.hpp"

namespace vi {

// A peak of |v| or |theta|: position x/l and dimensionless amplitude (docs/model.md §9):
// |v| sqrt(rho A l) for displacement, |theta| l sqrt(rho A l) for rotation, of a mass-normalised shape.
struct ShapePeak {
    double x = 0.0;
    double amplitude = 0.0;
};

// Zeros and peaks of one shape, positions as x/l in increasing order.
struct ShapeFeatures {
    std::vector<double> nodes;            // zeros of v (y_ij); ends where v is fixed are excluded
    std::vector<double> rotation_nodes;   // zeros of theta (phi_ij); ends where theta is fixed excluded
    std::vector<ShapePeak> peaks;         // local maxima of |v| (Y_ij), free ends included
    std::vector<ShapePeak> rotation_peaks;  // local maxima of |theta| (Phi_ij)
};

// Features of a global DOF vector (e.g. expand_to_global of a mass-normalised mode).
ShapeFeatures shape_features(const System& s, const Eigen::VectorXd& global_shape);

// Real roots of c0 + c1 t + c2 t^2 + c3 t^3 in [lo, hi], ascending; exact zeros at the ends kept.
std::vector<double> cubic_roots_in(const Eigen::Vector4d& c, double lo, double hi);
// Same, with the exact end values f(lo), f(hi) given (nodal DOFs: exact zeros stay exact).
std::vector<double> cubic_roots_in(const Eigen::Vector4d& c, double lo, double hi, double f_lo, double f_hi);

}  // namespace vi
