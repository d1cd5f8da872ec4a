#pragma once
// Two-node Euler-Bernoulli 2-D frame element: stiffness, consistent mass and Hermite interpolation.
// Local DOF order: [u1, v1, theta1, u2, v2, theta2] (axial, transverse [m]; rotation [rad]).

#include <Eigen/Dense>

namespace vi {

using ElementMatrix = Eigen::Matrix<double, 6, 6>;

// Section and material properties one element needs (SI).
struct ElementProperties {
    double E = 0.0;    // modulus [Pa]
    double A = 0.0;    // area [m^2]
    double I = 0.0;    // second moment [m^4]
    double rho = 0.0;  // density [kg/m^3]
};

// Stiffness matrix of an element of length L [m]: axial EA/L and cubic bending EI/L^3 blocks [N/m].
ElementMatrix element_stiffness(const ElementProperties& p, double L);

// Consistent mass matrix of an element of length L [m]: linear axial and cubic Hermite bending [kg].
ElementMatrix element_mass(const ElementProperties& p, double L);

// Geometric stiffness of an element of length L [m] per unit axial force (tension positive) [1/m]:
// int N_i' N_j' dx on the bending DOFs (the Hermite cubics), zero on the axial ones. N G q is the
// transverse force an axial force N exerts through the slope.
ElementMatrix element_geometric_stiffness(double L);

// Transverse displacement v at local coordinate xi in [0, 1] from nodal (v1, theta1, v2, theta2).
double hermite_v(double xi, double L, double v1, double t1, double v2, double t2);

// Slope dv/dx at xi from the same nodal values [rad].
double hermite_slope(double xi, double L, double v1, double t1, double v2, double t2);

// Coefficients c0..c3 of v(xi) = c0 + c1 xi + c2 xi^2 + c3 xi^3 on one element.
Eigen::Vector4d hermite_v_coefficients(double L, double v1, double t1, double v2, double t2);

}  // namespace vi
