// The damage indicators of each impact (dynamics/transient_result.hpp, impacts/impact_summary.hpp):
// the energy a Hertz contact dissipates against the point mass's kinetic energy lost and the
// Hunt-Crossley restitution, Hertz's peak pressure against Johnson's closed form, the yield onset
// 1.6 Y, the episodes' energies against the run's ledger, the summary's keys and the case keys'
// refusals.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "dynamics/cvode/cvode_solver.hpp"
#include "forces/hertz_contact.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "report/transient_output.hpp"
#include "support/run_command.hpp"
#include "hertz_point_mass.hpp"
#include "transient_fixtures.hpp"

namespace vi {
namespace damage_test {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

using test::hertz::falling_mass;
using test::hertz::gold_k;
using test::hertz::gold_star;
using test::hertz::kMass;
using test::hertz::kRadius;
using test::hertz::tight;

// The energy the damped contact takes from a point mass is its kinetic energy lost,
// (1 - e^2) m v^2 / 2 with e the Hunt-Crossley restitution at alpha v; undamped, nothing.
TEST(ContactDamage, PointMassLosesTheContactEnergyOfItsRestitution) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double e : {1.0, 0.9, 0.5}) {
        for (const double v : {0.1, 1.0}) {
            SCOPED_TRACE("e " + std::to_string(e) + ", v " + std::to_string(v));
            const double alpha = e < 1.0 ? hunt_crossley_damping(e, v) : 0.0;
            const TransientResult r = solve_cvode(falling_mass(v, alpha, 1.0, nan), {}, tight());
            ASSERT_EQ(r.episodes.size(), 1u);
            const ContactEpisode& ep = r.episodes[0];
            const double k0 = 0.5 * kMass * v * v;
            EXPECT_LT(std::abs(ep.contact_energy - (1.0 - e * e) * k0) / k0, 1e-6);
            EXPECT_LT(std::abs(ep.contact_energy - 0.5 * kMass * (ep.v_in * ep.v_in - ep.v_out * ep.v_out)) / k0, 1e-7);
            EXPECT_LT(std::abs(ep.contact_energy - r.final_energy.contact_dissipated) / k0, 1e-7);
        }
    }
}

// Hertz's peak pressure p0 = 3 F / (2 pi a^2), a = (3 F R / (4 E*))^(1/3) (Johnson 1985, eq. 4.21
// and 4.22), at the impact's peak force k d_max^(3/2), d_max = (5 m v^2 / (4 k))^(2/5); the impact
// yields exactly when p0 passes 1.6 Y (Johnson 1985, eq. 6.9).
TEST(ContactDamage, PeakPressureIsHertzsAndYieldOnsetIsAt1Point6Y) {
    const double v = 0.5;
    const double d_max = std::pow(5.0 * kMass * v * v / (4.0 * gold_k()), 0.4);
    const double f = gold_k() * std::pow(d_max, 1.5);
    const double a = std::cbrt(3.0 * f * kRadius / (4.0 * gold_star()));
    const double p0 = 3.0 * f / (2.0 * std::numbers::pi * a * a);
    for (const double margin : {0.99, 1.01}) {
        const double y = margin * p0 / 1.6;
        const TransientResult r = solve_cvode(falling_mass(v, 0.0, 1.0, y), {}, tight());
        ASSERT_EQ(r.episodes.size(), 1u);
        const ContactEpisode& ep = r.episodes[0];
        EXPECT_LT(rel(ep.peak_pressure, p0), 1e-6);
        ASSERT_TRUE(ep.yielded.has_value());
        EXPECT_EQ(*ep.yielded, margin < 1.0) << margin;
    }
    const TransientResult none = solve_cvode(falling_mass(v, 0.0), {}, tight());
    EXPECT_FALSE(none.episodes.at(0).yielded.has_value());
}

// The switch example: the energies of its episodes (every bounce on the dimple) add up to the
// contact dissipation of the run's ledger, each impact's to those of its episodes, and the summary
// gives them with the peak pressure.
TEST(ContactDamage, EpisodeEnergiesAddUpToTheLedgerThroughEveryImpact) {
    Case c = read_case_file(test::source_path("examples/switch/cantilever_switch_hertz.toml"));
    c.solver.rtol = 1e-10;
    c.supports[0].params.numbers["yield_strength"] = 300e6;
    const SimulationRun run = run_simulation(c);
    const TransientResult& r = run.result;
    ASSERT_GE(r.episodes.size(), 5u);
    double sum = 0.0;
    for (const ContactEpisode& e : r.episodes) {
        EXPECT_GE(e.contact_energy, 0.0);
        EXPECT_GT(e.peak_pressure, 0.0);
        sum += e.contact_energy;
    }
    const double total = r.final_energy.contact_dissipated;
    std::printf("switch: %zu episodes dissipate %.6e J in the contact, the ledger %.6e J\n", r.episodes.size(), sum, total);
    EXPECT_GT(total, 0.0);
    EXPECT_LT(std::abs(sum - total), 1e-6 * total);
    double impacts = 0.0;
    for (const Impact& im : run.summary.impacts) impacts += im.contact_energy;
    EXPECT_LT(std::abs(impacts - sum), 1e-12 * sum);
    const ContactDamage d = contact_damage(run.summary.impacts);
    EXPECT_TRUE(d.yield_known);
    const nlohmann::json j = transient_summary_json(c, run.built, r, run.summary, run.switching ? &*run.switching : nullptr);
    EXPECT_DOUBLE_EQ(j.at("contact_damage").at("impacts_contact_energy_j").get<double>(), d.contact_energy);
    EXPECT_DOUBLE_EQ(j.at("contact_damage").at("peak_pressure_pa").get<double>(), d.peak_pressure);
    EXPECT_EQ(j.at("contact_damage").at("yield_impacts").get<int>(), d.yield_impacts);
    EXPECT_TRUE(j.at("impacts").at(0).contains("peak_pressure_pa"));
    EXPECT_TRUE(j.at("episodes").at(0).contains("contact_energy_j"));
}

std::string error_of(const std::string& text) {
    try {
        read_case_text(text, "damage.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const std::string kBeam =
    "[beam]\nlength = \"117 um\"\nwidth = \"30 um\"\nthickness = \"2 um\"\nelements = 20\n"   // lines 1-5
    "[material]\nyoungs_modulus = \"207 GPa\"\ndensity = 8902\npoisson_ratio = 0.31\n"  // 6-9
    "[solver]\nmethod = \"cvode\"\nhorizon = \"10 us\"\n";  // 10-12
const std::string kSupport =
    "[[supports]]\nposition = 1.0\nlaw = \"hertz\"\nradius = \"2 um\"\neffective_modulus = 1e9\n";  // 13-17

TEST(ContactDamage, CaseKeysAreReadAndRefusedByName) {
    const Case c = read_case_text(kBeam + kSupport + "yield_strength = \"300 MPa\"\nhardness = \"1 GPa\"\n"
                                  "wear_coefficient = 1e-4\n", "damage.toml");
    EXPECT_EQ(c.supports[0].params.number("yield_strength"), 300e6);
    EXPECT_EQ(c.supports[0].params.number("wear_coefficient"), 1e-4);
    EXPECT_EQ(error_of(kBeam + kSupport + "yield_strength = \"-1 MPa\"\n"),
              "damage.toml:18: supports[0].yield_strength: must be positive");
    EXPECT_EQ(error_of(kBeam + kSupport + "hardness = 0\nwear_coefficient = 1e-4\n"),
              "damage.toml:18: supports[0].hardness: must be positive");
    EXPECT_EQ(error_of(kBeam + kSupport + "hardness = 1e9\nwear_coefficient = 2\n"),
              "damage.toml:19: supports[0].wear_coefficient: must lie in (0, 1]");
    EXPECT_EQ(error_of(kBeam + kSupport + "hardness = 1e9\nwear_coefficient = 0\n"),
              "damage.toml:19: supports[0].wear_coefficient: must lie in (0, 1]");
    EXPECT_EQ(error_of(kBeam + kSupport + "wear_coefficient = 1e-4\n"),
              "damage.toml:18: supports[0].wear_coefficient: needs hardness (the wear volume is K E / H)");
    EXPECT_EQ(error_of(kBeam + kSupport + "hardness = 1e9\n"),
              "damage.toml:18: supports[0].hardness: needs resistivity (the plastic contact radius) or "
              "wear_coefficient (the wear estimate)");
    EXPECT_EQ(error_of(kBeam + "[[supports]]\nposition = 1.0\nstiffness = 10\nyield_strength = 1e8\n"),
              "damage.toml:16: supports[0].yield_strength: only with supports[0].law = \"hertz\"");
}

// The command refuses an out-of-range key with exit 2 and writes nothing.
TEST(ContactDamage, CommandRefusesABadYieldStrengthWithExitTwo) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "vi_damage_key";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string file = (dir / "case.toml").string();
    std::ofstream(file) << kBeam << kSupport << "yield_strength = \"-1 MPa\"\n";
    const test::CommandResult r = test::run_vibroimpact({"simulate", file, "--out", (dir / "out").string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("case.toml:18: supports[0].yield_strength: must be positive"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    std::filesystem::remove_all(dir);
}

}  // namespace damage_test
}  // namespace vi
