// The Hertz contact law of a support (forces/hertz_contact.hpp): a point mass on it against Hertz's
// impact closed form (Johnson, Contact Mechanics, 1985, §11.4), the Hunt-Crossley restitution at the
// reference speed, the energy ledger through every impact of the switch example, the cantilever on a
// stiff dimple against the Kelvin-Voigt contact of the same secant stiffness, and the case keys.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "dynamics/cvode/cvode_solver.hpp"
#include "forces/hertz_contact.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "report/contact_resistance.hpp"
#include "report/transient_output.hpp"
#include "support/run_command.hpp"
#include "hertz_point_mass.hpp"
#include "transient_fixtures.hpp"

namespace vi {
// Named, not anonymous: the helpers' short names stay apart from other files of a unity batch.
namespace hertz_test {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

using test::hertz::falling_mass;
using test::hertz::gold_k;
using test::hertz::kMass;
using test::hertz::kRadius;
using test::hertz::tight;

// Hertz's impact of a point mass (Johnson 1985, eq. 11.24-11.25): d_max = (5 m v^2 / (4 k))^(2/5),
// F_max = k d_max^(3/2), contact time t_c = 2 (d_max / v) Int_0^1 du / sqrt(1 - u^(5/2))
// = (4/5) sqrt(pi) Gamma(2/5) / Gamma(9/10) d_max / v = 2.9432 d_max / v; the mass leaves at v.
TEST(HertzContact, PointMassImpactMatchesHertzClosedForm) {
    const double c_t = 0.8 * std::sqrt(std::numbers::pi) * std::tgamma(0.4) / std::tgamma(0.9);
    EXPECT_NEAR(c_t, 2.9432, 1e-4);  // 2.94328, quoted truncated
    for (const double sign : {1.0, -1.0}) {
        for (const double v : {0.05, 1.0}) {
            SCOPED_TRACE("sign " + std::to_string(sign) + ", v " + std::to_string(v));
            const TransientResult r = solve_cvode(falling_mass(v, 0.0, sign), {}, tight());
            ASSERT_EQ(r.episodes.size(), 1u);
            const ContactEpisode& ep = r.episodes[0];
            const double d_max = std::pow(5.0 * kMass * v * v / (4.0 * gold_k()), 0.4);
            EXPECT_LT(rel(ep.t_off - ep.t_on, c_t * d_max / v), 1e-6);
            EXPECT_LT(rel(ep.peak_penetration, d_max), 1e-6);
            EXPECT_LT(rel(ep.peak_force, gold_k() * std::pow(d_max, 1.5)), 1e-6);
            EXPECT_LT(rel(std::abs(ep.v_out / ep.v_in), 1.0), 1e-6);
            EXPECT_LT(rel(ep.impulse, 2.0 * kMass * v), 1e-6);
        }
    }
}

// The calibration: e(0) = 1; for small a = alpha v, 1 - e^2 = (4/3) a to first order (the energy the
// damper takes along the undamped impact, Int k alpha d^(3/2) (dd/dt)^2 dt = (2/3) a m v^2, which is
// Lankarani and Nikravesh's relation alpha = 3 (1 - e^2) / (4 v)); for large a, e -> 1/a.
TEST(HertzContact, HuntCrossleyRestitutionHasItsLimits) {
    EXPECT_NEAR(hunt_crossley_restitution(0.0), 1.0, 1e-10);
    for (const double a : {1e-3, 1e-2}) {
        const double e = hunt_crossley_restitution(a);
        EXPECT_NEAR((1.0 - e * e) / a, 4.0 / 3.0, 2.0 * a) << a;
    }
    EXPECT_NEAR(hunt_crossley_restitution(100.0), 0.01, 1e-12);
    for (const double e : {0.95, 0.7, 0.3}) EXPECT_NEAR(hunt_crossley_restitution(hunt_crossley_damping(e, 1.0)), e, 1e-12);
    EXPECT_THROW((void)hunt_crossley_damping(0.0, 1.0), std::invalid_argument);
    EXPECT_THROW((void)hunt_crossley_damping(1.5, 1.0), std::invalid_argument);
}

// A mass that meets the damped contact at the reference speed leaves with e times it (through CVODE
// and the element, independent of the calibration's own integration); at twice the speed the
// restitution is that of twice the a; the kinetic energy lost is the contact dissipation.
TEST(HertzContact, RestitutionAtTheReferenceSpeedIsTheOneAskedFor) {
    const double v_ref = 0.3;
    for (const double e : {0.9, 0.7, 0.4}) {
        const double alpha = hunt_crossley_damping(e, v_ref);
        for (const double v : {v_ref, 2.0 * v_ref}) {
            SCOPED_TRACE("e " + std::to_string(e) + ", v " + std::to_string(v));
            const TransientResult r = solve_cvode(falling_mass(v, alpha, 1.0), {}, tight());
            ASSERT_EQ(r.episodes.size(), 1u);
            const double expected = v == v_ref ? e : hunt_crossley_restitution(alpha * v);
            EXPECT_LT(rel(std::abs(r.episodes[0].v_out / r.episodes[0].v_in), expected), 1e-6);
            const double k0 = 0.5 * kMass * v * v;
            EXPECT_LT(std::abs(k0 - r.final_energy.kinetic - r.final_energy.contact_dissipated) / k0, 1e-7);
            EXPECT_GT(r.final_energy.contact_dissipated, 0.0);
        }
    }
}

// The switch example: the energy ledger closes at every sample through every bounce on the dimple.
TEST(HertzContact, EnergyLedgerClosesThroughEveryImpact) {
    Case c = read_case_file(test::source_path("examples/switch/cantilever_switch_hertz.toml"));
    c.solver.rtol = 1e-10;  // at the example's 1e-8 the ledger drifts by 1.3e-6
    const SimulationRun run = run_simulation(c);
    const TransientResult& r = run.result;
    ASSERT_GE(r.episodes.size(), 5u);
    const auto total = [](const EnergyLedger& e) {
        return e.kinetic + e.strain + e.contact_spring + e.electrical + e.rayleigh_dissipated + e.contact_dissipated +
               e.film_dissipated - e.external_work;
    };
    const double scale = std::abs(r.initial_energy.electrical);
    const double start = total(r.initial_energy);
    double worst = 0.0;
    for (const EnergyLedger& e : r.history.energy) worst = std::max(worst, std::abs(total(e) - start) / scale);
    std::printf("switch on a Hertz dimple: %zu episodes, ledger drift at most %.2e of C V^2/2\n", r.episodes.size(), worst);
    EXPECT_LT(worst, 1e-6);
    EXPECT_GT(r.final_energy.contact_dissipated, 0.0);
    EXPECT_EQ(run.built.model.forces[run.built.model.contacts.at(0).element]->kind(), "Hertz contact");
}

// The cantilever's tip dropped onto a stiff dimple and onto a Kelvin-Voigt contact of the same secant
// stiffness F_max / d_max: only the impacts differ. For a point mass of the same peak the two contact
// times are 2.9432 d/v and pi sqrt(4/5) d/v = 2.8099 d/v, 4.6 % apart; on the beam the impact's
// duration T2 is mostly the beam's (the tip held while the beam swings, docs/paper-parameters.md),
// so T2 and the period of impact vibrations T differ by less than 4.6 % of T2 (measured: 0.8 % and
// 0.1 %).
TEST(HertzContact, StiffDimpleAgreesWithKelvinVoigtOfTheSameSecantStiffness) {
    Case c = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    c.solver.method = SolverSettings::Method::cvode;
    c.solver.horizon = 30e-6;
    c.solver.rtol = 1e-10;
    Case hertz = c;
    hertz.supports[0].params.texts["law"] = "hertz";
    hertz.supports[0].params.numbers["radius"] = kRadius;
    hertz.supports[0].params.numbers["effective_modulus"] = effective_modulus(79e9, 0.42, 79e9, 0.42);
    const SimulationRun h = run_simulation(hertz);
    ASSERT_FALSE(h.result.episodes.empty());
    const ContactEpisode& first = h.result.episodes[0];
    Case kv = c;
    kv.supports[0].stiffness = first.peak_force / first.peak_penetration;
    kv.supports[0].damping_ratio.reset();
    kv.supports[0].damping = 0.0;
    const SimulationRun k = run_simulation(kv);
    ASSERT_TRUE(h.summary.T_first && k.summary.T_first && h.summary.T2_first && k.summary.T2_first);
    const double t2 = *h.summary.T2_first;
    std::printf("Kc = %.4g N/m, T2 %.5g / %.5g us, T %.5g / %.5g us\n", kv.supports[0].stiffness, t2 * 1e6,
                *k.summary.T2_first * 1e6, *h.summary.T_first * 1e6, *k.summary.T_first * 1e6);
    EXPECT_LT(std::abs(t2 - *k.summary.T2_first), 0.046 * t2);
    EXPECT_LT(std::abs(*h.summary.T_first - *k.summary.T_first), 0.046 * t2);
}

// The static solver on a Hertz support: the cantilever resting on a dimple pushed 50 nm into its
// unloaded tip carries F = k d^(3/2) = (3 E I / l^3) (p - d) (the Hermite elements' tip stiffness is
// exact), solved here by bisection on d. The static solve stops at a residual of 1e-12 of the largest
// term of K q (0.2 N of the nodes' shear against 0.4 uN at the tip), so F agrees to about 1e-6
// (measured 1.6e-6), and d, a small difference of displacements, to the same.
TEST(HertzContact, StaticEquilibriumOnAPrestressedDimple) {
    Case c = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    c.solver.method = SolverSettings::Method::cvode;
    c.solver.horizon = 1e-6;
    c.initial.kind = InitialState::Kind::rest;
    Support& s = c.supports[0];
    s.surface = 50e-9;
    s.surface_key = "prestress";
    s.params.texts["law"] = "hertz";
    s.params.numbers["radius"] = kRadius;
    s.params.numbers["youngs_modulus"] = 207e9;
    s.params.numbers["poisson_ratio"] = 0.31;
    const SimulationRun run = run_simulation(c);
    const double k = hertz_stiffness(effective_modulus(207e9, 0.31, 207e9, 0.31), kRadius);
    const double ei = c.material.youngs_modulus * c.beam.width * std::pow(c.beam.thickness, 3) / 12.0;
    const double k_tip = 3.0 * ei / std::pow(c.beam.length, 3);
    double lo = 0.0, hi = 50e-9;
    for (int i = 0; i < 200 && hi - lo > 1e-25; ++i) {
        const double d = 0.5 * (lo + hi);
        (k * std::pow(d, 1.5) > k_tip * (50e-9 - d) ? hi : lo) = d;
    }
    const double d = 0.5 * (lo + hi);
    ASSERT_FALSE(run.result.history.contact_force.empty());
    EXPECT_LT(rel(run.result.history.contact_force[0][0], k * std::pow(d, 1.5)), 1e-5);
    EXPECT_LT(rel(50e-9 - run.result.history.contact_v[0][0], d), 1e-5);
    EXPECT_GT(d, 1e-10);  // the dimple is pressed in, not just touched
}

// Holm's constriction resistance of the elastic Hertz spot at three forces: a = (3 F R / (4 E*))^(1/3)
// (Johnson 1985, eq. 4.22), R_c = rho / (2a) (Holm 1967); with a film, + sigma_f / (pi a^2); with a
// hardness, the plastic radius sqrt(F / (pi H)) once it is the larger; with a mean free path, Wexler's
// R = 4 rho lambda / (3 pi a^2) + Gamma(lambda / a) rho / (2a), which tends to Sharvin's term alone.
TEST(HertzContact, HolmResistanceMatchesTheClosedFormAtThreeForces) {
    const double star = effective_modulus(79e9, 0.42, 79e9, 0.42), k = gold_k(), rho = 2.2e-8;
    const auto element = [&](const ContactResistance& m) {
        return HertzContact("supports[0]", 0, 1.0, 0.0, 0.0, k, 0.0, kRadius, m);
    };
    const auto at_force = [&](const HertzContact& e, double F) {
        const double q = -std::pow(F / k, 2.0 / 3.0), v = 0.0;
        return e.contact_resistance(ElementState{0.0, &q, &v, nullptr});
    };
    ContactResistance holm;
    holm.resistivity = rho;
    ContactResistance film = holm;
    film.film_resistivity = 1e-12;
    ContactResistance hard = holm;
    hard.hardness = 1e9;
    ContactResistance wexler = holm;
    wexler.mean_free_path = 38e-9;
    for (const double F : {1e-6, 1e-5, 1e-4}) {
        SCOPED_TRACE("F = " + std::to_string(F));
        const double a = std::cbrt(3.0 * F * kRadius / (4.0 * star));
        const double area = std::numbers::pi * a * a;
        EXPECT_LT(rel(at_force(element(holm), F), rho / (2.0 * a)), 1e-12);
        EXPECT_LT(rel(at_force(element(film), F), rho / (2.0 * a) + 1e-12 / area), 1e-12);
        const double a_plastic = std::sqrt(F / (std::numbers::pi * hard.hardness));
        EXPECT_LT(rel(at_force(element(hard), F), rho / (2.0 * std::max(a, a_plastic))), 1e-12);
        const double kn = 38e-9 / a;
        const double r_w = 4.0 * rho * 38e-9 / (3.0 * area) + (1.0 + 0.83 * kn) / (1.0 + 1.33 * kn) * rho / (2.0 * a);
        EXPECT_LT(rel(at_force(element(wexler), F), r_w), 1e-12);
    }
    // The plastic radius takes over above F = (pi H)^3 (3 R / (4 E*))^2, 30 uN here: between the forces.
    EXPECT_GT(std::sqrt(1e-4 / (std::numbers::pi * 1e9)), std::cbrt(3.0 * 1e-4 * kRadius / (4.0 * star)));
    EXPECT_LT(std::sqrt(1e-6 / (std::numbers::pi * 1e9)), std::cbrt(3.0 * 1e-6 * kRadius / (4.0 * star)));
    // Ballistic limit: lambda >> a leaves Sharvin's 4 rho lambda / (3 pi a^2).
    ContactResistance ballistic = holm;
    ballistic.mean_free_path = 1e-3;
    const double a = std::cbrt(3.0 * 1e-5 * kRadius / (4.0 * star));
    EXPECT_LT(rel(at_force(element(ballistic), 1e-5), 4.0 * rho * 1e-3 / (3.0 * std::numbers::pi * a * a)), 1e-3);
    // Open, and without a model.
    const double q = 1e-9, v = 0.0;
    EXPECT_TRUE(std::isinf(element(holm).contact_resistance(ElementState{0.0, &q, &v, nullptr})));
    EXPECT_TRUE(std::isnan(HertzContact("supports[0]", 0, 1.0, 0.0, 0.0, k, 0.0, kRadius).contact_resistance(
        ElementState{0.0, &q, &v, nullptr})));
}

// The switch example's resistance: inf in the CSV while open, the element's value while closed; the
// summary's end value and the time from which it stays below r_on, read off the same samples.
TEST(HertzContact, ResistanceHistoryAndSummary) {
    const Case c = read_case_file(test::source_path("examples/switch/cantilever_switch_hertz.toml"));
    const SimulationRun run = run_simulation(c);
    const std::vector<ResistanceSeries> series = contact_resistances(run.built.model, run.result);
    ASSERT_EQ(series.size(), 1u);
    const ResistanceSeries& s = series[0];
    const TimeHistory& h = run.result.history;
    ASSERT_EQ(s.ohm.size(), h.t.size());
    EXPECT_EQ(s.r_on, 0.5);
    std::size_t open = 0, closed = 0, last_above = 0;
    for (std::size_t i = 0; i < h.t.size(); ++i) {
        if (h.contact_force[0][i] > 0.0) {
            ++closed;
            EXPECT_TRUE(std::isfinite(s.ohm[i]));
        } else {
            ++open;
            EXPECT_TRUE(std::isinf(s.ohm[i]));
        }
        if (!(s.ohm[i] < 0.5)) last_above = i;
    }
    EXPECT_GT(open, 100u);
    EXPECT_GT(closed, 100u);
    const nlohmann::json j = transient_summary_json(c, run.built, run.result, run.summary)["contact_resistance"][0];
    EXPECT_EQ(j["contact"], "supports[0]");
    EXPECT_EQ(j["closed_at_end"], true);
    EXPECT_EQ(j["resistance_end_ohm"].get<double>(), s.ohm.back());
    EXPECT_EQ(j["below_r_on_from_s"].get<double>(), h.t[last_above + 1]);
    EXPECT_GT(h.t[last_above + 1], run.summary.impacts.front().t_on);
    const std::string csv = history_csv(run.result, "tip", false, series).str();
    EXPECT_NE(csv.find("contact0_resistance_ohm\n"), std::string::npos);
    EXPECT_NE(csv.find(",inf\n"), std::string::npos);
    std::printf("switch on a Hertz dimple: R at the end %.4g ohm, below r_on = 0.5 ohm from %.4g us\n",
                s.ohm.back(), j["below_r_on_from_s"].get<double>() * 1e6);
}

std::string error_of(const std::string& text) {
    try {
        read_case_text(text, "hertz.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const std::string kBeam =
    "[beam]\nlength = \"117 um\"\nwidth = \"30 um\"\nthickness = \"2 um\"\nelements = 20\n"   // lines 1-5
    "[material]\nyoungs_modulus = \"207 GPa\"\ndensity = 8902\npoisson_ratio = 0.31\n"  // 6-9
    "[solver]\nmethod = \"cvode\"\nhorizon = \"10 us\"\n";  // 10-12
const std::string kSupport = "[[supports]]\nposition = 1.0\nlaw = \"hertz\"\nradius = \"2 um\"\n";  // 13-16

TEST(HertzContact, CaseKeysAreReadAndRefusedByName) {
    const Case c = read_case_text(kBeam + kSupport + "youngs_modulus = \"79 GPa\"\npoisson_ratio = 0.42\n"
                                  "restitution = 0.8\nreference_speed = \"0.5 m/s\"\n", "hertz.toml");
    EXPECT_EQ(c.supports[0].params.text("law"), "hertz");
    EXPECT_EQ(c.supports[0].params.number("youngs_modulus"), 79e9);
    EXPECT_FALSE(c.supports[0].linear_law());
    EXPECT_EQ(error_of(kBeam + kSupport + "effective_modulus = \"-1 GPa\"\n"),
              "hertz.toml:17: supports[0].effective_modulus: must be positive");
    EXPECT_EQ(error_of(kBeam + "[[supports]]\nposition = 1.0\nlaw = \"hertz\"\nradius = 0\neffective_modulus = 1e9\n"),
              "hertz.toml:16: supports[0].radius: must be positive");
    EXPECT_EQ(error_of(kBeam + kSupport + "effective_modulus = 1e9\nrestitution = 0\nreference_speed = 1\n"),
              "hertz.toml:18: supports[0].restitution: must lie in (0, 1]");
    EXPECT_EQ(error_of(kBeam + kSupport + "effective_modulus = 1e9\nrestitution = 1.5\nreference_speed = 1\n"),
              "hertz.toml:18: supports[0].restitution: must lie in (0, 1]");
    EXPECT_EQ(error_of(kBeam + kSupport + "effective_modulus = 1e9\nrestitution = 0.5\n"),
              "hertz.toml:18: supports[0].restitution: needs reference_speed (the impact speed the restitution is "
              "measured at)");
    EXPECT_EQ(error_of(kBeam + kSupport + "youngs_modulus = 1e9\n"),
              "hertz.toml:13: supports[0].poisson_ratio: missing required key");
    EXPECT_EQ(error_of(kBeam + kSupport + "effective_modulus = 1e9\nyoungs_modulus = 1e9\n"),
              "hertz.toml:18: supports[0].youngs_modulus: only with supports[0].law = \"hertz\" and without "
              "supports[0].effective_modulus");
    EXPECT_EQ(error_of(kBeam + kSupport + "effective_modulus = 1e9\nstiffness = 1000\n"),
              "hertz.toml:18: supports[0].stiffness: only with supports[0].law = \"kelvin-voigt\" (the linear contact)");
    EXPECT_EQ(error_of(kBeam + "[[supports]]\nposition = 1.0\nstiffness = 10\nradius = \"2 um\"\n"),
              "hertz.toml:16: supports[0].radius: only with supports[0].law = \"hertz\"");
    const std::string exact = "[beam]\nlength = \"117 um\"\nwidth = \"30 um\"\nthickness = \"2 um\"\nelements = 20\n"
                              "[material]\nyoungs_modulus = \"207 GPa\"\ndensity = 8902\npoisson_ratio = 0.31\n"
                              "[solver]\nmethod = \"exact\"\nhorizon = \"10 us\"\n";
    EXPECT_EQ(error_of(exact + kSupport + "effective_modulus = 1e9\n"),
              "hertz.toml:11: solver.method: \"exact\" cannot take the Hertz contact of supports[0].law (its force "
              "k d^(3/2) is not one of the exact solver's linear forms); use \"cvode\" or \"auto\"");
}

// The command refuses the exact solver with exit 2 and writes nothing.
TEST(HertzContact, CommandRefusesTheExactSolverWithExitTwo) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "vi_hertz_exact";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string file = (dir / "case.toml").string();
    std::ofstream(file) << "[beam]\nlength = \"117 um\"\nwidth = \"30 um\"\nthickness = \"2 um\"\nelements = 20\n"
                           "[material]\nyoungs_modulus = \"207 GPa\"\ndensity = 8902\npoisson_ratio = 0.31\n"
                           "[solver]\nmethod = \"exact\"\nhorizon = \"10 us\"\n"
                        << kSupport << "effective_modulus = 1e9\n";
    const test::CommandResult r = test::run_vibroimpact({"simulate", file, "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("case.toml:11: solver.method: \"exact\" cannot take the Hertz contact"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "summary.json"));
    std::filesystem::remove_all(dir);
}

}  // namespace hertz_test
}  // namespace vi
