#pragma once
// The quality factor of a beam's first mode in air against pressure: the modal estimate from the
// squeeze film's damping at rest, and the one a ring-down transient measures (docs/squeeze-film.md §5).

#include <optional>
#include <string>
#include <vector>

#include "model/case.hpp"
#include "plot/figure_gnuplot.hpp"

namespace vi {

// One pressure. Q_modal = omega1 m1 / c1 with m1 = phi1^T M phi1 and c1 = phi1^T C_film phi1 (the
// films' damping matrix at rest); Q_ringdown from the transient's tip maxima (a linear one-mode
// fit: decay rate a and damped frequency omega_d give Q = sqrt(omega_d^2 + a^2) / (2 a)), absent
// when fewer than three maxima rise above the noise (an overdamped or critically damped beam).
struct AirQPoint {
    double pressure = 0.0;          // [Pa]
    double knudsen = 0.0;           // lambda / g of the first film [-]
    double viscosity_ratio = 0.0;   // mu_eff / mu [-]
    double squeeze_number = 0.0;    // at omega1 [-]
    double q_modal = 0.0;           // [-]
    std::optional<double> q_ringdown;
    int maxima = 0;                 // tip maxima the ring-down fit used
};

struct AirQOptions {
    double amplitude = 1e-3;  // ring-down amplitude of the tip over the gap [-]
    int periods = 10;         // ring-down length [first-mode periods]
    int samples = 200;        // history samples per period
};

// Most elements of the Q study: its ring-down evaluates the film at every quadrature point of the
// mesh (17 pressures of the switch example: 3 s at m = 50, about 6 s at 100), while Q of mode 1
// is mesh-converged by m = 20 (to 5e-8; at m = 200 roundoff moves it 1e-7).
inline constexpr int kMaxAirQElements = 100;

// The case as the Q study runs it: [air] (defaults where the case has none), a film of gap `gap`
// [m] under the whole beam when the case has neither electrodes nor [[films]], no supports, no
// Rayleigh damping, no loads or voltages, released at rest with a first-mode velocity. InputError
// on beam.elements above kMaxAirQElements.
Case air_q_case(const Case& base, double gap);

// Q at one pressure [Pa] of a case made by air_q_case.
AirQPoint air_q_point(const Case& c, double pressure, const AirQOptions& o = {});

// Pressures from 1 atm down to 1 Pa, three per decade (log-spaced) [Pa].
std::vector<double> air_q_pressures();

// The CSV (pressure_pa, knudsen, viscosity_ratio, squeeze_number, q_modal, q_ringdown, maxima;
// q_ringdown the missing-value marker where there is none) and its log-log figure.
std::string air_q_csv(const std::vector<AirQPoint>& points);
FigureSpec air_q_figure(const std::vector<AirQPoint>& points, const std::string& case_name);

}  // namespace vi
