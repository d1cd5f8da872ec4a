#pragma once
// The reference for time-dependent loads: one mass on a spring and a damper under a point load
// F g(t), with its response in closed form (harmonic, step and ramp forcing), and how far a solver's
// time history and energy ledger are from it.

#include "dynamics/transient_problem.hpp"
#include "dynamics/transient_result.hpp"
#include "model/time_function.hpp"

namespace vi {

struct LoadedOscillator {
    double mass = 1e-11;     // [kg]
    double stiffness = 10.0; // [N/m]
    double zeta = 0.0;       // damping ratio, as mass-proportional Rayleigh damping alpha = 2 zeta omega [-]
    double force = 1e-6;     // F [N]
    double q0 = 0.0;         // released at rest from q0 [m]
    TimeFunction g;          // harmonic, step, or a table {0, t1} -> {0, 1} (a ramp, then held)

    [[nodiscard]] double omega() const;   // undamped circular frequency [rad/s]
    [[nodiscard]] double period() const;  // 2 pi / omega [s]
    // The problem both solvers take: one DOF, the load "loads[0]", no contact.
    [[nodiscard]] TransientProblem problem(double t_end, double output_step) const;
    // q(t) [m] in closed form. The ramp is solved undamped from rest only; any other combination
    // throws std::invalid_argument.
    [[nodiscard]] double response(double t) const;
};

// Largest |q - closed form| over the samples relative to `scale` [m], and largest departure of the
// energy ledger (kinetic + strain + damper work - external work - E(0)) relative to its largest term.
struct LoadResponseError {
    double response = 0.0;
    double ledger = 0.0;
};
LoadResponseError load_response_error(const LoadedOscillator& o, const TransientResult& r, double scale);

}  // namespace vi
