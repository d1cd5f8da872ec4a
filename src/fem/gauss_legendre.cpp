#include "fem/gauss_legendre.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace vi {

QuadratureRule gauss_legendre(int n) {
    if (n < 1 || n > 64) throw std::invalid_argument("gauss_legendre: 1 to 64 points");
    // Legendre's three-term recurrence gives the symmetric tridiagonal Jacobi matrix with
    // off-diagonal k / sqrt(4 k^2 - 1); its eigenvalues are the nodes on [-1, 1] and the squared
    // first components of its eigenvectors, times 2, the weights.
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(n, n);
    for (int k = 1; k < n; ++k) {
        const double b = k / std::sqrt(4.0 * k * k - 1.0);
        j(k, k - 1) = b;
        j(k - 1, k) = b;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(j);
    QuadratureRule r;
    for (int i = 0; i < n; ++i) {
        r.nodes.push_back(0.5 * (es.eigenvalues()[i] + 1.0));
        const double v = es.eigenvectors()(0, i);
        r.weights.push_back(v * v);  // 2 v^2 on [-1, 1], halved on [0, 1]
    }
    return r;
}

}  // namespace vi
