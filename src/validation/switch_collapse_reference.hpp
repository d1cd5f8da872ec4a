#pragma once
// An independent reduced-order model of a cantilever contact switch stepped to a voltage: Galerkin on
// the analytic clamped-free Euler-Bernoulli modes, a parallel-plate electrode, a Kelvin-Voigt stop
// under the free end, classical RK4 with located contact switches. Shares no code with the FE model
// (docs/validation.md): it tells whether the closed switch collapses onto its electrode, and when.

namespace vi {

// The switch as plain numbers (SI), the beam clamped at x = 0 and free at x = l.
struct CantileverSwitchSpec {
    double length = 0.0, width = 0.0, thickness = 0.0;  // l, w, t [m]
    double youngs_modulus = 0.0, density = 0.0;         // E [Pa], rho [kg/m^3]
    double electrode_from = 0.0, electrode_to = 1.0;    // the electrode's span under the beam [x/l]
    double electrode_gap = 0.0;                         // beam to electrode at rest [m]
    double electrode_width = 0.0;                       // [m]
    double stop_gap = 0.0;                              // the stop's surface lies stop_gap below the free end [m]
    double stop_stiffness = 0.0;                        // Kc [N/m]
    // Cc = 2 zeta_c sqrt(Kc rho A l / 4): the first mode's effective mass at the free end.
    double stop_damping_ratio = 0.0;
    double damping_ratio_1 = 0.0, damping_ratio_2 = 0.0;  // Rayleigh damping through modes 1 and 2
    double horizon = 0.0;                               // [s]
    double collapse_fraction = 0.01;  // collapsed once the narrowest air gap falls to this fraction of the gap
    int modes = 16;                   // Galerkin modes
    double step = 1e-9;               // RK4 step [s] (shortened near the electrode)
};

// One run from rest, the voltage stepped on at t = 0.
struct SwitchRomRun {
    bool closed = false;          // the free end reached the stop
    double closing_time = 0.0;    // first contact with the stop [s]
    bool collapsed = false;       // the beam reached the electrode within the horizon
    double collapse_time = 0.0;   // [s]
    double collapse_x = 0.0;      // where the air gap is narrowest then [x/l]
    int contact_switches = 0;     // stop closures and openings located
};

SwitchRomRun cantilever_switch_rom(const CantileverSwitchSpec& s, double voltage);

// The lowest step voltage that collapses the switch within its horizon, bisected in [lo, hi] (lo must
// stay, hi collapse) to a bracket no wider than `width` [V]; returns {stays, collapses}.
struct VoltageBracket {
    double stays = 0.0, collapses = 0.0;  // [V]
};
VoltageBracket cantilever_switch_rom_threshold(const CantileverSwitchSpec& s, double lo, double hi, double width);

}  // namespace vi
