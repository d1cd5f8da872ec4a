// Section 12 of the validation report: the checks that run in the test suite only (their measured
// figures are in the documents named), with the published formulas they test against. Static text:
// nothing here is computed, so nothing here can go stale against the code's output. A force element's
// family adds its own item (ElementFamily::validation), after these.

#include "validation/report.hpp"

#include "problem/element_families.hpp"

namespace vi::validation_detail {

std::string section_elsewhere() {
    std::string families;
    for (const ElementFamily* family : element_families()) {
        if (const std::string item = family->validation(); !item.empty()) families += "- " + item + "\n";
    }
    return "## 12. Validated in the test suite (figures in the documents named)\n\n"
           "These checks run in `ctest`; their measured figures are in the documents named, not recomputed here.\n\n"
           "- **Beams held at both ends** (`tests/axial_stress_test.cpp`; docs/electrostatics.md §8): frequencies "
           "under residual stress against the pinned-pinned closed form omega_n = (n pi / l)^2 sqrt(EI / (rho A)) "
           "sqrt(1 + N0 l^2 / (n^2 pi^2 EI)) (S. S. Rao, *Vibration of Continuous Systems*, 2007, ch. 11) and the "
           "clamped-clamped characteristic equation of EI w'''' - N0 w'' = rho A omega^2 w; pull-in with mid-plane "
           "stretching against an independent shooting solution.\n"
           "- **Sections and layers** (`tests/beam_sections_test.cpp`; docs/model.md §2.1): a two-section stepped "
           "cantilever's first three frequencies against the exact ones of the segmented Euler-Bernoulli beam, the "
           "roots of its 8 x 8 determinant (y = a cos bx + b sin bx + c cosh bx + d sinh bx per segment, b^4 = "
           "omega^2 rho A / EI; clamp, continuity of y, y', EI y'', EI y''' at the step, free end: the transfer "
           "matrix of segmented beams, e.g. S. S. Rao, *Vibration of Continuous Systems*, 2007, ch. 11), "
           "root-found in the test, the error falling with m as h^4; a uniform beam written as one section and as "
           "two equal sections bit for bit the plain beam, as one layer to roundoff; a bilayer's released "
           "curvature against Timoshenko's bimetal strip kappa = 6 d (1 + m)^2 / (h (3 (1 + m)^2 + (1 + m n)(m^2 + "
           "1 / (m n)))) (S. Timoshenko, *J. Opt. Soc. Am.* 11 (1925) 233; d the layers' free-strain mismatch, m "
           "and n their thickness and modulus ratios) to 1e-9; a layer's stress gradient curling by Gamma / E; an "
           "electrode's force at rest over two widths eps0 V^2 / (2 g^2) times the area it faces; the energy "
           "ledger through the transient of the stepped, layered, curled paddle switch "
           "(examples/devices/ohmic_paddle_switch.toml).\n"
           "- **Adhesion** (`tests/adhesion_test.cpp`; docs/adhesion.md §8): pull-off forces 2 pi R w (DMT: "
           "Derjaguin, Muller and Toporov, *J. Colloid Interface Sci.* 53 (1975) 314) and 1.5 pi R w (JKR: "
           "Johnson, Kendall and Roberts, *Proc. R. Soc. Lond. A* 324 (1971) 301); the release threshold "
           "P* = F_po (1 + k / Kc) of a one-degree-of-freedom contact, static and transient; the detached length "
           "l_d = (3 E t^3 h^2 / (2 gamma))^(1/4) of the S-shaped stuck cantilever (Mastrangelo and Hsu, "
           "*J. Microelectromech. Syst.* 2 (1993) 33 and 44) against the FE energy balance; the energy ledger through "
           "adhesive impacts.\n"
           "- **Adhesion on a dielectric layer** (`tests/dielectric_adhesion_test.cpp`; docs/adhesion.md §9-11): the "
           "peel balance of a beam held on an adhesive layer against the clamped-guided span's closed forms (release "
           "rate 18 E I h^2 / s^4, restoring force 12 E I h / l_d^3, critical work of adhesion 1.5 E t^3 h^2 / l^4); "
           "the detached length of the S-shaped stuck cantilever on the compliant layer tending to the closed form "
           "l_d (Mastrangelo and Hsu 1993) as 1 / (b l_d) with b = (k / (4 E I))^(1/4) (Hetenyi's beam on an elastic "
           "foundation, 1946); the FE beam settled on the layer with the full law against that solution; the energy "
           "ledger through landing, sticking and release.\n"
           "- **Hertz contact** (`tests/hertz_contact_test.cpp`; docs/hertz-contact.md): a point mass on the "
           "Hertz law k d^(3/2), k = (4/3) E* sqrt(R), against Hertz's impact (K. L. Johnson, *Contact Mechanics*, "
           "1985, §11.4): contact time (4/5) sqrt(pi) Gamma(2/5) / Gamma(9/10) d_max / v = 2.9432 d_max / v, "
           "d_max = (5 m v^2 / (4 k))^(2/5) and the peak force k d_max^(3/2), to 1e-6 through CVODE; the "
           "Hunt-Crossley damping (Hunt and Crossley, *J. Appl. Mech.* 42 (1975) 440) calibrated to a restitution "
           "at a reference speed, against the impact measured through CVODE to 1e-6 and against the first-order "
           "relation 1 - e^2 = (4/3) alpha v (Lankarani and Nikravesh, *J. Mech. Des.* 112 (1990) 369); the energy "
           "ledger through every bounce of the switch example; the cantilever on a stiff dimple against the "
           "Kelvin-Voigt contact of the same secant stiffness (T2 and T within 4.6 % of T2, the point-mass "
           "contact-time ratio); the contact resistance against Holm's constriction rho / (2a) of the Hertz radius "
           "(R. Holm, *Electric Contacts*, 1967), with a film, the plastic radius sqrt(F / (pi H)), and Wexler's "
           "interpolation (G. Wexler, *Proc. Phys. Soc.* 89 (1966) 927) to Sharvin's term 4 rho lambda / (3 pi a^2) "
           "(Yu. V. Sharvin, *Sov. Phys. JETP* 21 (1965) 655) at three forces, to 1e-12.\n"
           "- **Electrical bounce** (`tests/electrical_bounce_test.cpp`; docs/hertz-contact.md §7): an undamped "
           "point mass on a gold Hertz dimple with Holm's resistance conducts below r_on = R(d_on) for 2 (d_max "
           "/ v) Int_(u_on)^1 du / sqrt(1 - u^(5/2)), u_on = d_on / d_max, centred on its impact (the time "
           "Hertz's impact spends deeper than d_on, from its energy integral; Johnson 1985, §11.4), to 1e-6 at "
           "u_on = 0.25, 0.5 and 0.9, its smallest resistance Holm's at d_max to 1e-6; the switch example's "
           "electrical bounces equal its mechanical openings with r_on above every closed resistance, and it is "
           "never on below the smallest; the same stretches at two output steps.\n"
           "- **Squeeze-film damping** (`tests/squeeze_film_test.cpp`; docs/squeeze-film.md §8): the long rigid "
           "strip c = mu w^3 L / g^3 (Reynolds equation across a narrow plate); the rarefied viscosity "
           "mu / (1 + 9.638 Kn^1.159) (Veijola et al., *Sens. Actuators A* 48 (1995) 239) against Burgdorfer's "
           "1 + 6 Kn (1959) and Hsia and Domoto's 1 + 6 Kn + 6 Kn^2 (1983) at small Kn; the finite-plate factor "
           "(Blech, *J. Lubr. Technol.* 105 (1983) 615); the quality factor of the paper's cantilever in air from a "
           "ring-down against the modal estimate omega_1 m / c.\n"
           "- **Calibration** (`tests/fit_test.cpp`; docs/calibration.md): synthetic recovery of Kc, zeta_c and "
           "zeta_1 from a noisy tip trajectory inside the 95 % intervals, intervals that scale with the noise, and an "
           "exact trade-off (E and nu through E / (1 - nu^2)) reported as undetermined.\n"
           "- **Optimisation** (`tests/optimize_test.cpp`; docs/optimization.md): the lowest rebound z_max over the "
           "support position against a 141-point grid search of the paper's study, and a binding constraint "
           "held on its boundary.\n"
           "- **Fabrication spread** (`tests/cli_uq_test.cpp`, `tests/uq_estimators_test.cpp`, "
           "`tests/sweep_analyses_test.cpp`; docs/uq.md): the FE pull-in voltage of a full-length-electrode "
           "cantilever without fringing is V0 (t / t0)^1.5 (g / g0)^1.5 to 1e-9; with thickness and gap lognormal, "
           "log V_PI is normal of known mean and variance, and the estimated mean, SD, 5 and 95 % quantiles and a "
           "yield lie within their 95 % intervals; the Sobol indices of that law against their closed forms "
           "(e^{s_a^2} - 1) / (e^{s_a^2 + s_b^2} - 1); the Ishigami function's indices (Ishigami and Homma, "
           "*Proc. ISUMA* 1990) through the same estimators (Saltelli et al., *Comput. Phys. Commun.* 181 (2010) "
           "259; Jansen, *Comput. Phys. Commun.* 117 (1999) 35) to 0.01, their bootstrap intervals holding the "
           "closed forms in 94 % of 360 cases; the coverage of the mean's t interval, the quantiles' order-statistic "
           "intervals (Hahn and Meeker 1991) and Wilson's yield interval (Wilson 1927) over 2000 independent "
           "samples; a resumed study and one on another thread count give the same uq.json byte for byte.\n" +
           families;
}

}  // namespace vi::validation_detail
