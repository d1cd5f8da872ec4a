#pragma once
// ReducedElement: a force element evaluated directly in the coordinates of a reduced basis (q = P eta
// over its DOFs), for a model of a few modes whose element spans many DOFs (an electrode over a fine
// mesh): its force and tangent come out projected, at a cost that follows its own quadrature and the
// basis size, not the mesh. Made by ForceElement::reduced (docs/architecture.md).

#include <cstddef>

namespace vi {

// The basis rows of an element's DOFs: P (|dofs| x r, column-major, P(i, j) = data[i + j |dofs|]),
// so that the element's displacements are q = P eta [m, rad] for basis coordinates eta.
struct BasisRows {
    const double* data = nullptr;
    std::size_t dofs = 0;
    std::size_t size = 0;  // r
};

// An element's state in basis coordinates: the time [s], eta and d eta / dt (r entries each).
struct ReducedState {
    double t = 0.0;
    const double* eta = nullptr;
    const double* eta_dot = nullptr;
};

// The element on one basis. Each member equals the element's own evaluation at q = P eta,
// v = P eta' projected onto the basis (P^T f, P^T df/dq P, P^T df/dv P) to roundoff: it is the same
// quadrature, reordered. Offered by elements that are not contacts and have no watch functions
// (their episode readings and watches stay on the element itself).
class ReducedElement {
public:
    virtual ~ReducedElement() = default;
    // Adds P^T f in `mode` to `force` (r entries) and returns the power the element dissipates [W].
    virtual double add_force_and_power(const ReducedState& s, int mode, double* force) const = 0;
    // Adds P^T (df/dq) P to dfdq and P^T (df/dv) P to dfdv (r x r, row-major).
    virtual void add_tangent(const ReducedState& s, int mode, double* dfdq, double* dfdv) const = 0;
    // ForceElement::input_power and switching_function at q = P eta, v = P eta'.
    [[nodiscard]] virtual double input_power(const ReducedState& s, int mode) const = 0;
    [[nodiscard]] virtual double switching_function(const ReducedState& s, int mode) const = 0;
};

}  // namespace vi
