#include "model/magnitude_checks.hpp"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <utility>

#include "model/run_estimate.hpp"
#include "model/number_format.hpp"

// The values a case file gives are held to the window by check_key_values (model/key_checks.hpp);
// here the scales derived from several of them, which can leave the window when each value is in it
// (a thickness of 1e-45 m gives a second moment of 1e-135 m^4).

namespace vi {
namespace {

const std::string kWindow = "1e-100 to 1e100";

bool in_window(double v) { return std::abs(v) >= 1.0 / kMagnitudeLimit && std::abs(v) <= kMagnitudeLimit; }

// A derived scale: reported on the contributing key whose value lies farthest from 1 (in decades),
// the one most likely written in the wrong unit.
void derived(std::vector<CaseProblem>& out, const char* what, double v,
             std::initializer_list<std::pair<const char*, double>> from) {
    if (std::isfinite(v) && in_window(v)) return;
    const char* key = from.begin()->first;
    double worst = -1.0;
    for (const auto& [k, x] : from) {
        const double decades = std::abs(std::log10(std::abs(x)));
        if (decades > worst) {
            worst = decades;
            key = k;
        }
    }
    out.push_back({key, "gives " + std::string(what) + " = " + significant(v, 3) + ", outside " + kWindow +
                            " (SI): the problem cannot be computed in double precision (docs/case-files.md, Limits)"});
}

bool usable(double v) { return std::isfinite(v) && v > 0.0 && in_window(v); }

// The beam's derived scales and the supports against the beam; only once its own values are usable.
void check_scales(std::vector<CaseProblem>& out, const Case& c) {
    const Beam& b = c.beam;
    const double l = b.length, w = b.width, t = b.thickness, e = c.material.effective_modulus();
    const double rho = c.material.density;
    if (!(usable(l) && usable(w) && usable(t) && usable(e) && usable(rho)) || b.elements < 1) return;
    const std::pair<const char*, double> L{"beam.length", l}, W{"beam.width", w}, T{"beam.thickness", t},
        E{"material.youngs_modulus", e}, R{"material.density", rho};
    const RunEstimate est = estimate_run(c);
    const std::size_t before = out.size();
    derived(out, "the section area w t [m^2]", b.area(), {W, T});
    derived(out, "the second moment w t^3/12 [m^4]", b.second_moment(), {T, W});
    derived(out, "the bending stiffness EI [N m^2]", e * b.second_moment(), {E, T, W});
    derived(out, "the mass per length rho A [kg/m]", rho * b.area(), {R, W, T});
    derived(out, "the beam's mass rho A l [kg]", rho * b.area() * l, {R, W, T, L});
    derived(out, "the stiffness scale EI/l^3 [N/m]", est.bending_stiffness, {E, W, T, L});
    if (est.omega1 > 0.0) derived(out, "omega_1^2 [1/s^2]", est.omega1 * est.omega1, {E, R, T, L});
    derived(out, "the mesh's highest omega^2 [1/s^2]", est.omega_top * est.omega_top, {E, R, T, L});
    if (out.size() != before) return;

    const double k_beam = est.bending_stiffness;
    const double rho_a_l = rho * b.area() * l;
    for (std::size_t i = 0; i < c.supports.size(); ++i) {
        const Support& s = c.supports[i];
        const std::string at = "supports[" + std::to_string(i) + "].";
        if (!usable(s.stiffness)) continue;
        const double stiff = s.stiffness / k_beam;
        if (stiff > kMaxContactRatio) {
            out.push_back({at + "stiffness", significant(s.stiffness, 3) + " N/m is " + significant(stiff, 3) +
                                                 " times the beam's EI/l^3 = " + significant(k_beam, 3) +
                                                 " N/m; above 1e9 times the contact force is lost to roundoff "
                                                 "(docs/case-files.md, Limits)"});
            continue;
        }
        // The damper's force at omega_1 against the same bound; a ratio with mode 1's smallest
        // effective mass (rho A l / 4) in place of the one at the support.
        const bool ratio = s.damping_ratio.has_value();
        const double cc = ratio ? 2.0 * *s.damping_ratio * std::sqrt(s.stiffness * rho_a_l / 4.0) : s.damping;
        if (!std::isfinite(cc) || cc < 0.0 || (ratio && !in_window(*s.damping_ratio) && *s.damping_ratio != 0.0)) continue;
        const double damp = cc * est.omega1 / k_beam;
        if (damp > kMaxContactRatio) {
            out.push_back({at + (ratio ? "damping_ratio" : "damping"),
                           "gives a damper force at omega_1 " + significant(damp, 3) + " times the beam's EI/l^3 = " +
                               significant(k_beam, 3) + " N/m; above 1e9 times the contact force is lost to roundoff "
                               "(docs/case-files.md, Limits)"});
        }
    }
}

}  // namespace

void check_magnitudes(std::vector<CaseProblem>& out, const Case& c) { check_scales(out, c); }

}  // namespace vi
