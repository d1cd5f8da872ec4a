#pragma once
// Gauss-Legendre quadrature on [0, 1]: nodes and weights, exact for polynomials of degree 2n - 1.

#include <vector>

namespace vi {

struct QuadratureRule {
    std::vector<double> nodes;    // in (0, 1), ascending
    std::vector<double> weights;  // summing to 1
};

// The n-point rule (1 <= n <= 64), from the eigenvalues of the Jacobi matrix (Golub and Welsch,
// Math. Comp. 23, 1969). Throws std::invalid_argument for n outside that range.
QuadratureRule gauss_legendre(int n);

}  // namespace vi
