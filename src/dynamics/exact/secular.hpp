#pragma once
// Roots of the secular equation of one Kelvin-Voigt contact on a damped modal system:
// g(z) = 1 + (kc + cc z) sum_i s_i / (z^2 + c_i z + k_i) = 0 [z in 1/s], by Aberth-Ehrlich iteration.

#include <complex>
#include <vector>

namespace vi {

using cd = std::complex<double>;

// One coupled mode: s = phi_c^2 [1/kg], c = 2 zeta omega [1/s], k = omega^2 [1/s^2], and the two
// roots of z^2 + c z + k (its free poles; a conjugate pair or two reals).
struct SecularMode {
    double s = 0.0, c = 0.0, k = 0.0;
    cd pole_a, pole_b;
};

// A root set closed under conjugation: `z` holds the real roots and one root of each conjugate pair
// (Im z > 0); `paired[k]` says z[k] stands for the pair.
struct ConjugateRoots {
    std::vector<cd> z;
    std::vector<bool> paired;
};

// All 2 m roots (m = modes.size()), conjugate-symmetric by construction. kc [N/m / kg], cc [N s/m / kg]
// are the contact's stiffness and damping (the modes are mass normalised). Returns false when the
// iteration does not converge or the roots cannot be paired (the caller then falls back to a dense
// solve). When the system is undamped (every c = 0 and cc = 0) the roots are put on the imaginary axis.
bool secular_roots(const std::vector<SecularMode>& modes, double kc, double cc, ConjugateRoots& out);

}  // namespace vi
