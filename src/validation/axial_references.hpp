#pragma once
// Independent references for beams held at both ends under an axial force (docs/electrostatics.md §8):
// closed forms and characteristic equations of the axially loaded beam, and a shooting solution of
// the clamped-clamped beam's pull-in with residual stress and mid-plane stretching. They share no
// code with the finite-element model.

#include <vector>

namespace vi {

// Section, material and axial force of a uniform beam (SI).
struct AxialBeam {
    double EI = 0.0;      // bending stiffness [N m^2]
    double EA = 0.0;      // axial stiffness [N]
    double rhoA = 0.0;    // mass per length [kg/m]
    double length = 0.0;  // l [m]
    double N0 = 0.0;      // residual axial force, tension positive [N]
};

// Pinned-pinned: omega_n = (n pi / l)^2 sqrt(EI / (rho A)) sqrt(1 + N0 l^2 / (n^2 pi^2 EI)) [rad/s]
// (the mode sin(n pi x / l) is exact for any N0 above buckling).
double pinned_pinned_axial_omega(const AxialBeam& b, int n);

// Clamped-clamped: the lowest `count` roots omega [rad/s] of
// 2 s1 s2 (1 - cosh(s1 l) cos(s2 l)) + (s1^2 - s2^2) sinh(s1 l) sin(s2 l) = 0,
// s1,2^2 = (sqrt(N0^2 + 4 EI rho A omega^2) +- N0) / (2 EI), the characteristic equation of
// EI w'''' - N0 w'' - rho A omega^2 w = 0 with w = w' = 0 at both ends; found by a scan and
// bisection (bounded loops). Throws std::runtime_error when fewer roots are found.
std::vector<double> clamped_clamped_axial_omegas(const AxialBeam& b, int count);

// Static pull-in of a clamped-clamped beam under an electrode over its whole span, parallel plate:
// EI w'''' - N w'' = eps0 w_e V^2 / (2 (g - w)^2), N = N0 + (EA / (2 l)) int w'^2 dx (when
// stretching), solved by shooting on half the span (RK4, Newton on w''(0), w'''(0), V^2 and N at a
// prescribed mid-span travel) and maximised over that travel.
struct BridgePullin {
    double voltage = 0.0;     // V_PI [V]
    double mid_travel = 0.0;  // mid-span travel at pull-in / gap [-]
};
BridgePullin bridge_pullin_shooting(const AxialBeam& b, double gap, double electrode_width, bool stretching);

}  // namespace vi
