#include "fem/buckling.hpp"

#include <Eigen/SparseCholesky>

#include <cmath>
#include <stdexcept>
#include <string>

namespace vi {
namespace {

// Inverse iteration: the Rayleigh quotient's error falls like (lambda_1 / lambda_2)^(2k), 0.35^k
// clamped at both ends, so a few tens of steps reach roundoff.
constexpr int kMaxSteps = 500;
constexpr double kTolerance = 1e-12;

}  // namespace

double buckling_force(const System& s) {
    const SparseMatrix G = submatrix(s.G, s.bending);
    const SparseMatrix K0 = SparseMatrix(submatrix(s.K, s.bending) - s.axial_force * G);
    const Eigen::SimplicialLDLT<SparseMatrix> ldlt(K0);
    if (ldlt.info() != Eigen::Success || (ldlt.vectorD().array() <= 0.0).any()) {
        throw std::runtime_error("buckling_force: the bending stiffness without the axial force is not positive definite");
    }
    // A start with some of every shape: uneven along the beam.
    Eigen::VectorXd y(K0.rows());
    for (Eigen::Index i = 0; i < y.size(); ++i) y[i] = 1.0 + 0.37 * std::sin(1.3 * static_cast<double>(i));
    double previous = 0.0;
    for (int step = 0; step < kMaxSteps; ++step) {
        const Eigen::VectorXd x = ldlt.solve(G * y);
        const double gx = x.dot(G * x);
        if (!(gx > 0.0)) throw std::runtime_error("buckling_force: the beam's geometric stiffness vanishes");
        const double lambda = x.dot(K0 * x) / gx;
        y = x / std::sqrt(gx);
        if (step > 0 && std::abs(lambda - previous) <= kTolerance * lambda) return lambda;
        previous = lambda;
    }
    throw std::runtime_error("buckling_force: the inverse iteration did not settle in " + std::to_string(kMaxSteps) +
                             " steps");
}

}  // namespace vi
