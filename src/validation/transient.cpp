// docs/validation.md sections 5 and 6: one mass on a Kelvin-Voigt contact against its closed form,
// and the energy of the bouncing cantilever, through both transient solvers.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <numbers>
#include <optional>
#include <sstream>

#include "model/run_control.hpp"
#include "impacts/impact_summary.hpp"
#include "validation/report.hpp"
#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/exact/exact_solver.hpp"

namespace vi::validation_detail {
namespace {

using Clock = std::chrono::steady_clock;


std::string wall(double s) { return " (" + fixed(s, 1) + " s)"; }

// Runs a solver, turning an exception into a message for the table.
struct Attempt {
    std::optional<TransientResult> result;
    std::string failure;
    double seconds = 0.0;
};

template <class Solve>
Attempt attempt(Solve solve) {
    Attempt a;
    const auto t0 = Clock::now();
    try {
        a.result = solve();
    } catch (const std::exception& e) {
        a.failure = e.what();
    }
    a.seconds = seconds_since(t0);
    return a;
}

double conserved(const EnergyLedger& e) { return e.kinetic + e.strain + e.contact_spring + e.electrical - e.external_work; }
double with_losses(const EnergyLedger& e) { return conserved(e) + e.rayleigh_dissipated + e.contact_dissipated; }

// Worst relative departure of f(E(t)) from f(E(0)) over the samples and at the end.
struct Drift {
    double worst = 0.0;
    double final = 0.0;
};

template <class F>
Drift drift(const TransientResult& r, F f) {
    Drift d;
    const double e0 = f(r.initial_energy);
    for (const EnergyLedger& e : r.history.energy) d.worst = std::max(d.worst, std::abs(f(e) - e0) / e0);
    d.final = std::abs(f(r.final_energy) - e0) / e0;
    d.worst = std::max(d.worst, d.final);
    return d;
}

// Impacts after grouping with the default gap (a quarter of the first period of the beam, m elements).
std::size_t impact_count(const TransientResult& r, const PiecewiseLinearProblem& p) {
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(p.K, p.M, Eigen::EigenvaluesOnly);
    ImpactSettings s;
    s.omega1 = std::sqrt(es.eigenvalues()[0]);
    s.length = 117e-6;
    return summarize_impacts(r, s).impacts.size();
}

}  // namespace

std::string section_single_dof(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 5. Single-DOF Kelvin-Voigt impact\n\n"
      << "A mass m = 1e-9 kg falls at v = 1 mm/s from h = 1 nm onto a Kelvin-Voigt contact "
         "Kc = 10 N/m, Cc = 2 zeta sqrt(Kc m), which acts only while it pushes (no tension: the mass "
         "leaves when F = Kc d + Cc dd/dt falls to zero, before d does). Closed form (Schwager and "
         "Poeschel 2007): with omega_n = sqrt(Kc/m), the contact lasts "
         "t_c = (pi - 2 asin zeta) / (omega_n sqrt(1 - zeta^2)) and the coefficient of restitution is "
         "e = exp(-zeta omega_n t_c). Computed: t_c = t_off - t_on and e = -v_out / v_in of the first "
         "episode. CVODE runs at its default rtol = 1e-10.\n\n";
    const double m = 1e-9, Kc = 10.0, v = 1e-3, h = 1e-9;
    const double wn = std::sqrt(Kc / m);
    Table t{{"quantity", "reference", "exact solver", "rel. error", "CVODE", "rel. error", "test asserts (exact / CVODE)"},
            {}};
    double cvode_seconds = 0.0;
    for (double zeta : {0.0, 0.1, 0.5, 0.9}) {
        const double Cc = 2.0 * zeta * std::sqrt(Kc * m);
        const double tc = (std::numbers::pi - 2.0 * std::asin(zeta)) / (wn * std::sqrt(1.0 - zeta * zeta));
        const double e = std::exp(-zeta * wn * tc);
        const PiecewiseLinearProblem p = single_dof_drop(m, Kc, Cc, h, v, h / v + 1.5 * tc);
        const Attempt ex = attempt([&] { return solve_exact(p); });
        const Attempt cv = attempt([&] { return solve_cvode(p); });
        cvode_seconds += cv.seconds;
        auto cells = [](const Attempt& a, double ref, bool duration) -> std::pair<std::string, std::string> {
            if (!a.result) return {"failed: " + a.failure, "-"};
            if (a.result->episodes.empty()) return {"no contact", "-"};
            const ContactEpisode& ep = a.result->episodes.front();
            const double val = duration ? ep.t_off - ep.t_on : -ep.v_out / ep.v_in;
            return {duration ? num(val * 1e6, 10) : num(val, 10), err(rel(val, ref))};
        };
        const std::string z = num(zeta, 2);
        const std::string cv_tol = zeta <= 0.5 ? "< 1e-7" : "-";
        const auto [ext, exe] = cells(ex, tc, true);
        const auto [cvt, cve] = cells(cv, tc, true);
        t.add({"t_c [us], zeta = " + z, num(tc * 1e6, 10), ext, exe, cvt, cve, "< 1e-8 / " + cv_tol});
        const auto [exr, exre] = cells(ex, e, false);
        const auto [cvr, cvre] = cells(cv, e, false);
        t.add({"e, zeta = " + z, num(e, 10), exr, exre, cvr, cvre, "< 1e-8 / " + cv_tol});
    }
    s << t.str() << "\n"
      << "The exact solver's bounds are `ExactSolver.SingleDofContactDurationAndRestitution` on this very "
         "problem; the CVODE bounds are `CvodeSolver.FreeMassImpactMatchesKelvinVoigtClosedForm` on its own "
         "drop (m = 1e-11 kg, Kc = 50 N/m, v = 0.1 m/s, zeta = 0, 0.1, 0.5).\n\n";
    report_progress(o, "section 5: single-DOF impact" + wall(cvode_seconds) + " in CVODE");
    return s.str();
}

std::string section_energy(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 6. Energy conservation and the energy ledger\n\n"
      << "The paper's cantilever dropped on a tip contact (zero gap) from a static tip lift of 1 um "
         "(`cantilever_drop` of `tests/transient_fixtures.hpp`), Kc = 40 N/m.\n\n"
      << "- **Undamped** (no Rayleigh, no contact damper): kinetic + strain + contact-spring energy must "
         "stay constant through every impact. Drift = max over the sampled history and the end of "
         "|E(t) - E(0)| / E(0).\n"
      << "- **Damped** (alpha = 2e3 1/s, beta = 2e-10 s, Cc = 5e-7 N s/m): the energy lost must "
         "equal the Rayleigh and contact-damper work the solver integrates. Ledger error = max of "
         "|E(t) + W_rayleigh(t) + W_contact(t) - E(0)| / E(0).\n\n";
    Table t{{"run", "episodes (impacts)", "quantity", "computed", "reference", "test asserts"}, {}};
    auto add = [&](const std::string& run, const PiecewiseLinearProblem& p, const Attempt& a, bool damped,
                   const std::string& tol) {
        if (!a.result) {
            t.add({run, "-", damped ? "ledger error" : "energy drift", "failed: " + a.failure, "0", tol});
            return;
        }
        const TransientResult& r = *a.result;
        const Drift d = damped ? drift(r, with_losses) : drift(r, conserved);
        const std::string count = std::to_string(r.episodes.size()) + " (" + std::to_string(impact_count(r, p)) + ")";
        std::string quantity = damped ? "ledger error" : "energy drift";
        if (damped) {
            const double e0 = with_losses(r.initial_energy);
            quantity += "; dissipated " + fixed(100.0 * (r.final_energy.rayleigh_dissipated + r.final_energy.contact_dissipated) / e0, 1) +
                        " % of E(0)";
        }
        t.add({run, count, quantity, err(d.worst), "0", tol});
    };

    const PiecewiseLinearProblem undamped10 = cantilever_drop(10, 40.0, 0.0, 1e-6, 0.0, 0.0, 1.5e-4);
    const PiecewiseLinearProblem damped10 = cantilever_drop(10, 40.0, 5e-7, 1e-6, 2e3, 2e-10, 1.2e-4);
    add("exact, undamped, m = 10, 150 us", undamped10, attempt([&] { return solve_exact(undamped10); }), false,
        "< 1e-8 (`UndampedEnergyIsConservedThroughTwentyImpacts`)");
    add("exact, damped, m = 10, 120 us", damped10, attempt([&] { return solve_exact(damped10); }), true,
        "< 1e-8 (`DampedEnergyLossEqualsDamperWork`)");
    report_progress(o, "section 6: exact solver energy");

    const PiecewiseLinearProblem undamped2 = cantilever_drop(2, 40.0, 0.0, 1e-6, 0.0, 0.0, 1.5e-4);
    CvodeOptions tight;
    tight.rtol = 1e-11;
    const Attempt cv2 = attempt([&] { return solve_cvode(undamped2, tight); });
    add("CVODE rtol 1e-11, undamped, m = 2, 150 us", undamped2, cv2, false,
        "< 1e-7 (`UndampedBeamConservesEnergyThroughImpacts`, Kc = 50)");
    report_progress(o, "section 6: CVODE undamped m = 2" + wall(cv2.seconds));
    if (!o.quick) {
        // About 5e6 steps (the default budget) are not enough for 150 us here.
        CvodeOptions many;
        many.max_steps = 20000000;
        const Attempt cv10 = attempt([&] { return solve_cvode(undamped10, many); });
        add("CVODE rtol 1e-10 (max_steps 2e7), undamped, m = 10, 150 us", undamped10, cv10, false, "-");
        report_progress(o, "section 6: CVODE undamped m = 10" + wall(cv10.seconds));
    }
    // --quick: the damped check on m = 2 as well (m = 10 takes seconds).
    const int md = o.quick ? 2 : 10;
    const PiecewiseLinearProblem damped_cv = o.quick ? cantilever_drop(2, 40.0, 5e-7, 1e-6, 2e3, 2e-10, 1.2e-4) : damped10;
    const Attempt cvd = attempt([&] { return solve_cvode(damped_cv); });
    add("CVODE rtol 1e-10, damped, m = " + std::to_string(md) + ", 120 us", damped_cv, cvd, true,
        md == 10 ? "< 1e-7 (`DampedBeamLedgerBalancesAndEpisodesAreSane`, Kc = 50)" : "-");
    report_progress(o, "section 6: CVODE damped m = " + std::to_string(md) + wall(cvd.seconds));
    s << t.str() << "\n"
      << "The exact solver propagates each contact state in closed form, so its drift is roundoff. CVODE's "
         "BDF method is slightly dissipative: undamped, it keeps every mode the impacts excite, so on "
         "m = 10 it must resolve the highest FE mode (about a million steps, some seconds)"
      << (o.quick ? " (with --quick both CVODE beam runs use m = 2)" : "")
      << "; the test suite checks the undamped case on m = 2.\n\n";
    return s.str();
}

}  // namespace vi::validation_detail
