#pragma once
// Rayleigh damping coefficients from two damping ratios at two circular frequencies (paper eq. 5).

namespace vi {

// C = alpha M + beta K.
struct RayleighCoefficients {
    double alpha = 0.0;  // mass-proportional [1/s]
    double beta = 0.0;   // stiffness-proportional [s]
};

// Solves alpha + beta w1^2 = 2 w1 xi1 and alpha + beta w2^2 = 2 w2 xi2 (w in rad/s, w1 != w2).
RayleighCoefficients rayleigh_from_ratios(double w1, double xi1, double w2, double xi2);

// Damping ratio the coefficients give a mode of circular frequency w: (alpha / w + beta w) / 2.
double rayleigh_ratio(const RayleighCoefficients& c, double w);

}  // namespace vi
