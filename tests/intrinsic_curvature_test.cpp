// The released curl ([curl], forces/intrinsic_curvature.hpp): the static shape of a uniform beam
// against the closed forms of a beam with stress-free curvature kappa0 (a cantilever's kappa0 x^2 / 2,
// exact for cubic Hermite elements; a single layer's kappa0 = Gamma / E; no motion when both ends are
// clamped), the pull-in voltage and the closing of the switch example curled up, the energy ledger
// through its transient, and the refusals of a curl given twice, not at all, or closing a gap.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "case_text_fixture.hpp"
#include "forces/intrinsic_curvature.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "problem/beam_model.hpp"
#include "statics/pullin.hpp"
#include "statics/static_solution.hpp"
#include "support/contract_elements.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "support/text_checks.hpp"

namespace vi {
// Named, not anonymous: the tests are compiled in unity batches, whose files share one namespace.
namespace curl_test {

// The contract's samples: moments on the two rotations of a one-element beam, as on a beam pinned at
// both ends, and the one moment a cantilever's free end keeps.
const bool kContractSamples = test::add_contract_element(
    {"intrinsic curvature, pinned ends", "intrinsic curvature",
     [] { return std::make_shared<IntrinsicCurvature>("curl", std::vector<int>{1, 3}, std::vector<double>{-2e-9, 2e-9}); }}) &&
                              test::add_contract_element(
    {"intrinsic curvature, free end", "intrinsic curvature",
     [] { return std::make_shared<IntrinsicCurvature>("curl", std::vector<int>{0}, std::vector<double>{3e-9}); }});

// The base case (l = 100 um, 20 elements, E = 200 GPa) with its ends and a [curl] table.
Case curled(const std::string& ends, const std::string& curl) {
    std::string text = test::kBaseCase;
    text.insert(text.find("[beam]\n") + 7, ends);
    return read_case_text(text + "[curl]\n" + curl, "curl.toml");
}

std::string beam_ends(const char* left, const char* right) {
    return std::string("left = \"") + left + "\"\nright = \"" + right + "\"\n";
}

// The static equilibrium's v and theta at every node: (x, v, theta).
struct NodeValue {
    double x, v, theta;
};

std::vector<NodeValue> static_shape(const Case& c) {
    const BeamModel b = build_beam_model(c);
    const StaticState s = solve_static(b.K, b.forces, Eigen::VectorXd::Zero(b.K.rows()), {}, 200);
    std::vector<NodeValue> out(b.system.mesh.x.size());
    for (std::size_t n = 0; n < out.size(); ++n) out[n] = {b.system.mesh.x[n], 0.0, 0.0};
    for (std::size_t i = 0; i < b.system.bending.size(); ++i) {
        const int global = b.system.free_dofs[static_cast<std::size_t>(b.system.bending[i])];
        NodeValue& n = out[static_cast<std::size_t>(global / 3)];
        (global % 3 == 1 ? n.v : n.theta) = s.q[static_cast<Eigen::Index>(i)];
    }
    return out;
}

// The largest difference from the closed form v(x), theta(x), relative to the largest |v| and |theta|.
double worst_relative(const std::vector<NodeValue>& shape, const std::function<double(double)>& v,
                      const std::function<double(double)>& theta) {
    double v_max = 0.0, t_max = 0.0, v_err = 0.0, t_err = 0.0;
    for (const NodeValue& n : shape) {
        v_max = std::max(v_max, std::abs(v(n.x)));
        t_max = std::max(t_max, std::abs(theta(n.x)));
        v_err = std::max(v_err, std::abs(n.v - v(n.x)));
        t_err = std::max(t_err, std::abs(n.theta - theta(n.x)));
    }
    return std::max(v_err / v_max, t_err / t_max);
}

TEST(IntrinsicCurvature, CantileverTakesTheArcKappaXSquaredOverTwo) {
    const double kappa0 = 1000.0, l = 100e-6;
    const std::vector<NodeValue> shape = static_shape(curled(beam_ends("clamped", "free"), "curvature = 1000\n"));
    const double tip = shape.back().v;
    std::printf("cantilever, kappa0 = 1000 1/m: tip lift %.15g um (kappa0 l^2 / 2 = %.15g um)\n", tip * 1e6,
                kappa0 * l * l / 2.0 * 1e6);
    EXPECT_NEAR(tip, kappa0 * l * l / 2.0, 1e-10 * kappa0 * l * l);
    // Cubic Hermite elements hold the quadratic exactly: every node to roundoff.
    EXPECT_LT(worst_relative(shape, [&](double x) { return kappa0 * x * x / 2.0; }, [&](double x) { return kappa0 * x; }),
              1e-10);
    // The same through the closed form the checks use.
    const Case c = curled(beam_ends("clamped", "free"), "curvature = 1000\n");
    EXPECT_NEAR(released_shape(c, kappa0, 0.4 * l), kappa0 * 0.16 * l * l / 2.0, 1e-15 * kappa0 * l * l);
}

// A single layer with a linear stress gradient Gamma through its thickness: the released moment
// Gamma I over EI, kappa0 = Gamma / E, a tip lift Gamma l^2 / (2 E).
TEST(IntrinsicCurvature, StressGradientGivesTipLiftGammaLSquaredOverTwoE) {
    const double gamma = 10e6 / 1e-6, e = 200e9, l = 100e-6;  // 10 MPa per um
    const Case c = curled(beam_ends("clamped", "free"), "stress_gradient = 1e13\n");
    EXPECT_DOUBLE_EQ(intrinsic_curvature(c), gamma / e);
    const double tip = static_shape(c).back().v;
    std::printf("stress gradient 10 MPa/um, E = 200 GPa: tip lift %.10g um (Gamma l^2 / (2E) = %.10g um)\n", tip * 1e6,
                gamma * l * l / (2.0 * e) * 1e6);
    EXPECT_NEAR(tip, gamma * l * l / (2.0 * e), 1e-10 * tip);
    // The plate modulus E / (1 - nu^2) of a wide beam curls it less.
    const Case wide = read_case_text(test::kBaseCase + "plate_modulus = true\n[curl]\nstress_gradient = 1e13\n", "w.toml");
    EXPECT_DOUBLE_EQ(intrinsic_curvature(wide), gamma * (1.0 - 0.09) / e);
    // Given as the tip lift itself.
    const Case lifted = curled(beam_ends("clamped", "free"), "tip_lift = \"0.8 um\"\n");
    EXPECT_NEAR(static_shape(lifted).back().v, 0.8e-6, 1e-10 * 0.8e-6);
}

TEST(IntrinsicCurvature, HeldEndsTakeTheirClosedForms) {
    const double kappa0 = -500.0, l = 100e-6;
    // Both ends clamped: the curl is held entirely; the model has no element for it.
    const Case cc = curled(beam_ends("clamped", "clamped"), "curvature = -500\n");
    const BeamModel b = build_beam_model(cc);
    for (const ForceElementPtr& e : b.forces) EXPECT_NE(e->name(), "curl");
    for (const NodeValue& n : static_shape(cc)) {
        EXPECT_EQ(n.v, 0.0);
        EXPECT_EQ(n.theta, 0.0);
    }
    EXPECT_EQ(released_shape(cc, kappa0, 0.3 * l), 0.0);
    // Both pinned: end moments EI kappa0 bend it into kappa0 (x^2 - l x) / 2.
    const std::vector<NodeValue> pp = static_shape(curled(beam_ends("pinned", "pinned"), "curvature = -500\n"));
    EXPECT_LT(worst_relative(pp, [&](double x) { return kappa0 * (x * x - l * x) / 2.0; },
                             [&](double x) { return kappa0 * (x - l / 2.0); }),
              1e-10);
    // Clamped and pinned: kappa0 l^2 (s^3 - s^2) / 4 with s = x / l.
    const std::vector<NodeValue> cp = static_shape(curled(beam_ends("clamped", "pinned"), "curvature = -500\n"));
    EXPECT_LT(worst_relative(cp, [&](double x) { const double s = x / l; return kappa0 * l * l * (s * s * s - s * s) / 4.0; },
                             [&](double x) { const double s = x / l; return kappa0 * l * (3.0 * s * s - 2.0 * s) / 4.0; }),
              1e-10);
}

Case switch_case(const std::string& extra) {
    const std::string path = test::source_path("examples/switch/cantilever_switch.toml");
    Case c = read_case_file(path);
    if (extra.empty()) return c;
    return read_case_text(test::read_text(path) + extra, "switch.toml");
}

// The switch example curled up by 0.5 um at its tip: its gaps at rest are the nominal ones plus the
// released shape, so its pull-in voltage rises, and lies between those of the straight switch with
// its electrode's gap widened uniformly by the shape's least and largest lift over the electrode
// (x/l = 0.1 and 0.9): a gap wider everywhere needs more voltage.
TEST(IntrinsicCurvature, CurlUpRaisesThePullInVoltageOfTheSwitchExample) {
    const double lift = 0.5e-6;
    const auto v_pi = [](const Case& c) {
        const PullinResult r = trace_pullin(c);
        EXPECT_TRUE(r.pullin.has_value());
        return r.pullin ? r.pullin->voltage : 0.0;
    };
    const auto widened = [&](double by) {
        Case c = switch_case("");
        c.electrodes[0].gap += by;
        c.supports[0].surface -= lift;  // the stop's gap at rest, as in the curled switch
        return c;
    };
    const double straight = v_pi(switch_case(""));
    const double curled_up = v_pi(switch_case("[curl]\ntip_lift = \"0.5 um\"\n"));
    const double curled_down = v_pi(switch_case("[curl]\ntip_lift = \"-0.2 um\"\n"));
    const double low = v_pi(widened(lift * 0.01)), high = v_pi(widened(lift * 0.81));
    std::printf("switch V_PI: straight %.6f V, curled up 0.5 um %.6f V (between %.6f and %.6f), down 0.2 um %.6f V\n",
                straight, curled_up, low, high, curled_down);
    EXPECT_GT(curled_up, straight);
    EXPECT_LT(curled_down, straight);
    EXPECT_GT(curled_up, low);
    EXPECT_LT(curled_up, high);
}

double ledger_total(const EnergyLedger& e) {
    return e.kinetic + e.strain + e.contact_spring + e.electrical + e.rayleigh_dissipated + e.contact_dissipated +
           e.film_dissipated - e.external_work;
}

// The curled switch starts at rest in its released shape (no motion before the voltage), closes
// later than the straight one (a wider gap), and its energy ledger closes at every sample with the
// curl's energy in the strain term.
TEST(IntrinsicCurvature, CurledSwitchClosesLaterAndItsLedgerCloses) {
    const auto run = [](const std::string& extra) {
        Case c = switch_case(extra);
        c.solver.rtol = 1e-10;
        c.solver.horizon = 20e-6;
        return run_simulation(c);
    };
    const SimulationRun straight = run("");
    const SimulationRun curled_up = run("[curl]\ntip_lift = \"0.3 um\"\n");
    const TransientResult& r = curled_up.result;
    ASSERT_FALSE(straight.result.episodes.empty());
    ASSERT_FALSE(r.episodes.empty());
    std::printf("switch closes at %.6g us straight, %.6g us curled up 0.3 um\n", straight.result.episodes[0].t_on * 1e6,
                r.episodes[0].t_on * 1e6);
    EXPECT_GT(r.episodes[0].t_on, straight.result.episodes[0].t_on);
    // At rest in the released shape: the tip starts 0.3 um up.
    ASSERT_FALSE(r.history.watched_v.empty());
    EXPECT_NEAR(r.history.watched_v.front(), 0.3e-6, 1e-9 * 0.3e-6);
    const double scale = std::abs(r.initial_energy.electrical) + std::abs(r.initial_energy.strain);
    const double start = ledger_total(r.initial_energy);
    double worst = 0.0;
    for (const EnergyLedger& e : r.history.energy) worst = std::max(worst, std::abs(ledger_total(e) - start) / scale);
    std::printf("curled switch: %zu episodes, ledger drift at most %.2e\n", r.episodes.size(), worst);
    EXPECT_LT(worst, 1e-6);
    EXPECT_LT(r.initial_energy.strain, 0.0);  // 1/2 q K q - f.q at the released shape: -1/2 f.q
}

std::string error_of(const std::string& text) {
    try {
        read_case_text(text, "curl.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(IntrinsicCurvature, TwoKeysNoKeyOrAClosedGapAreRefusedAtTheirLine) {
    // Lines 11 and 12: [curl] and its first key.
    EXPECT_EQ(error_of(test::kBaseCase + "[curl]\ncurvature = 10\ntip_lift = \"1 um\"\n").rfind("curl.toml:1", 0), 0u);
    EXPECT_NE(error_of(test::kBaseCase + "[curl]\ncurvature = 10\ntip_lift = \"1 um\"\n").find("curl.tip_lift"),
              std::string::npos);
    EXPECT_NE(error_of(test::kBaseCase + "[curl]\nstress_gradient = 1e12\ncurvature = 1\n").find("cannot be combined"),
              std::string::npos);
    EXPECT_EQ(error_of(test::kBaseCase + "[curl]\n"),
              "curl.toml:11: curl: give one of curvature, stress_gradient or tip_lift");
    // Curled down 2.5 um onto an electrode 2 um below over x/l 0.5 .. 1: closed at the tip by 0.5 um.
    const std::string electrode = "[[electrodes]]\nfrom = 0.5\nto = 1.0\ngap = \"2 um\"\nvoltage = \"1 V\"\n";
    const std::string closed = error_of(test::kBaseCase + electrode + "[curl]\ntip_lift = \"-2.5 um\"\n");
    EXPECT_EQ(closed.rfind("curl.toml:17: curl.tip_lift: the released shape", 0), 0u) << "[" << closed << "]";
    EXPECT_NE(closed.find("electrodes[0]"), std::string::npos) << closed;
    EXPECT_NE(closed.find("x = 100 um"), std::string::npos) << closed;
    EXPECT_NE(closed.find("0.5 um too far"), std::string::npos) << closed;
    // Pinned at both ends and curled up, the middle goes down by kappa0 l^2 / 8 = 1.25 um: it reaches
    // an electrode 1 um below over the whole span at x = l / 2, 0.25 um too far.
    std::string pinned = test::kBaseCase;
    pinned.insert(pinned.find("[beam]\n") + 7, beam_ends("pinned", "pinned"));
    const std::string middle = error_of(pinned + "[[electrodes]]\nfrom = 0.0\nto = 1.0\ngap = \"1 um\"\nvoltage = \"1 V\"\n[curl]\ncurvature = 1000\n");
    EXPECT_NE(middle.find(": curl.curvature: the released shape"), std::string::npos) << middle;
    EXPECT_NE(middle.find("x = 50 um (x/l = 0.5): it moves 1.25 um toward a gap of 1 um, 0.25 um too far"),
              std::string::npos)
        << middle;
    // Curled up, away from it: accepted; up onto a stop above 1 um over the tip: refused.
    EXPECT_EQ(error_of(test::kBaseCase + electrode + "[curl]\ntip_lift = \"2.5 um\"\n"), "");
    const std::string stop = "[[supports]]\nposition = 1.0\nside = \"above\"\ngap = \"1 um\"\nstiffness = 100\n";
    EXPECT_NE(error_of(test::kBaseCase + stop + "[curl]\ntip_lift = \"2.5 um\"\n").find("supports[0]"), std::string::npos);
    // A stop given as a prestress is pressed on purpose: the curl may press it further.
    const std::string pressed = "[[supports]]\nposition = 1.0\nside = \"above\"\nprestress = \"0.1 um\"\nstiffness = 100\n";
    EXPECT_EQ(error_of(test::kBaseCase + pressed + "[curl]\ntip_lift = \"2.5 um\"\n"), "");
}

// The command line: exit 2, one line naming the file, the line and the key, nothing written.
TEST(IntrinsicCurvature, SimulateRefusesACurlThatClosesTheGap) {
    const std::string dir = test::make_temp_dir();
    const std::string file = dir + "/curled.toml";
    test::write_text(file, test::read_text(test::source_path("examples/switch/cantilever_switch.toml")) +
                               "[curl]\ntip_lift = \"-2.5 um\"\n");
    const std::string out = dir + "/out";
    const auto r = test::run_vibroimpact({"simulate", file, "--out", out});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(test::is_one_error_line(r.err)) << r.err;
    EXPECT_NE(r.err.find(file + ":"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(": curl.tip_lift: "), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    std::filesystem::remove_all(dir);
}

TEST(IntrinsicCurvature, ContractSamplesAreRegistered) { EXPECT_TRUE(kContractSamples); }

}  // namespace curl_test
}  // namespace vi
