#pragma once
// LinearForm: how a piecewise-linear force element describes itself to the exact solver, which
// integrates exactly only these two kinds of term (docs/model.md §12).

#include <variant>
#include <vector>

#include "model/time_function.hpp"

namespace vi {

// A unilateral Kelvin-Voigt spring-damper on one transverse DOF: with sign = +1 (surface below) or
// -1 (above), penetration d = sign (surface - q[dof]) [m], force on the DOF sign F with
// F = Kc d + Cc dd/dt, acting only while d > 0 and F > 0 (no tension).
struct UnilateralSpringDamper {
    int dof = -1;
    double sign = 1.0;
    double surface = 0.0;    // [m]
    double stiffness = 0.0;  // Kc [N/m]
    double damping = 0.0;    // Cc [N s/m]
};

// A prescribed force amplitude g(t) distributed on DOFs with weights (a point force's consistent
// load vector: the Hermite shape values at the point) [N].
struct TimeForcing {
    std::vector<int> dofs;
    std::vector<double> weights;
    double amplitude = 0.0;  // [N]
    TimeFunction time;
};

struct LinearForm {
    std::variant<UnilateralSpringDamper, TimeForcing> term;
};

}  // namespace vi
