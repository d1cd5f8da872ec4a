#include "fem/beam_element.hpp"

namespace vi {

ElementMatrix element_stiffness(const ElementProperties& p, double L) {
    ElementMatrix k = ElementMatrix::Zero();
    const double ea = p.E * p.A / L;
    k(0, 0) = ea;
    k(0, 3) = -ea;
    k(3, 0) = -ea;
    k(3, 3) = ea;

    const double c = p.E * p.I / (L * L * L);
    const int b[4] = {1, 2, 4, 5};
    const double kb[4][4] = {{12, 6 * L, -12, 6 * L},
                             {6 * L, 4 * L * L, -6 * L, 2 * L * L},
                             {-12, -6 * L, 12, -6 * L},
                             {6 * L, 2 * L * L, -6 * L, 4 * L * L}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) k(b[i], b[j]) = c * kb[i][j];
    return k;
}

ElementMatrix element_mass(const ElementProperties& p, double L) {
    ElementMatrix m = ElementMatrix::Zero();
    const double ma = p.rho * p.A * L / 6.0;
    m(0, 0) = 2 * ma;
    m(0, 3) = ma;
    m(3, 0) = ma;
    m(3, 3) = 2 * ma;

    const double c = p.rho * p.A * L / 420.0;
    const int b[4] = {1, 2, 4, 5};
    const double mb[4][4] = {{156, 22 * L, 54, -13 * L},
                             {22 * L, 4 * L * L, 13 * L, -3 * L * L},
                             {54, 13 * L, 156, -22 * L},
                             {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m(b[i], b[j]) = c * mb[i][j];
    return m;
}

ElementMatrix element_geometric_stiffness(double L) {
    ElementMatrix g = ElementMatrix::Zero();
    const double c = 1.0 / (30.0 * L);
    const int b[4] = {1, 2, 4, 5};
    const double gb[4][4] = {{36, 3 * L, -36, 3 * L},
                             {3 * L, 4 * L * L, -3 * L, -L * L},
                             {-36, -3 * L, 36, -3 * L},
                             {3 * L, -L * L, -3 * L, 4 * L * L}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) g(b[i], b[j]) = c * gb[i][j];
    return g;
}

Eigen::Vector4d hermite_v_coefficients(double L, double v1, double t1, double v2, double t2) {
    // From N1 = 1 - 3xi^2 + 2xi^3, N2 = L(xi - 2xi^2 + xi^3), N3 = 3xi^2 - 2xi^3, N4 = L(-xi^2 + xi^3).
    const double a1 = L * t1;
    const double a2 = L * t2;
    return {v1, a1, -3 * v1 - 2 * a1 + 3 * v2 - a2, 2 * v1 + a1 - 2 * v2 + a2};
}

double hermite_v(double xi, double L, double v1, double t1, double v2, double t2) {
    const Eigen::Vector4d c = hermite_v_coefficients(L, v1, t1, v2, t2);
    return c[0] + xi * (c[1] + xi * (c[2] + xi * c[3]));
}

double hermite_slope(double xi, double L, double v1, double t1, double v2, double t2) {
    const Eigen::Vector4d c = hermite_v_coefficients(L, v1, t1, v2, t2);
    return (c[1] + xi * (2 * c[2] + xi * 3 * c[3])) / L;
}

}  // namespace vi
