// Beams held at both ends (docs/electrostatics.md §8): residual stress's frequencies against the
// axially loaded beam's closed form and characteristic equation, the mid-plane stretching element's
// contract, pull-in of a clamped-clamped bridge with stretching and residual stress against an
// independent shooting solution, and the refusals.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "statics/pullin.hpp"
#include "fem/system.hpp"
#include "forces/midplane_stretching.hpp"
#include "io/case_reader.hpp"
#include "modal/modal_analysis.hpp"
#include "model/case_checks.hpp"
#include "model/input_error.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "validation/axial_references.hpp"

namespace vi {
namespace {

// A 300 um x 50 um x 2 um bridge (E = 200 GPa), ends and axial keys given, an electrode below the
// whole span 3 um away.
Case bridge(int elements, const std::string& ends, const std::string& axial) {
    return read_case_text(R"(
[beam]
length = "300 um"
width = "50 um"
thickness = "2 um"
elements = )" + std::to_string(elements) + "\n" + ends + "\n" + axial + R"(
[material]
youngs_modulus = "200 GPa"
density = "8900 kg/m^3"
poisson_ratio = 0.31
[[electrodes]]
from = 0.0
to = 1.0
gap = "3 um"
voltage = "1 V"
)",
                          "bridge.toml");
}

AxialBeam reference_of(const Case& c) {
    const double E = c.material.effective_modulus();
    return {E * c.beam.second_moment(), E * c.beam.area(), c.material.density * c.beam.area(), c.beam.length,
            c.beam.residual_stress * c.beam.area()};
}

// Largest relative error of the lowest three FE bending frequencies against `exact`.
double worst_frequency_error(const Case& c, const std::vector<double>& exact) {
    const ModalResult r = analyse_modes(build_system(c), 3);
    double worst = 0.0;
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(r.bending[k].omega / exact[k] - 1.0));
    return worst;
}

TEST(ResidualStress, PinnedPinnedFrequenciesMatchTheAxiallyLoadedBeam) {
    const std::string ends = "left = \"pinned\"\nright = \"pinned\"";
    const double critical = buckling_stress(bridge(10, ends, ""));
    // Tension, none, and compression at 80 % of buckling (mode 1 falls to 45 % of its unloaded value).
    for (const double sigma : {50e6, 0.0, -0.8 * critical}) {
        const std::string axial = "residual_stress = \"" + std::to_string(sigma / 1e6) + " MPa\"";
        const AxialBeam b = reference_of(bridge(10, ends, axial));
        const std::vector<double> exact{pinned_pinned_axial_omega(b, 1), pinned_pinned_axial_omega(b, 2),
                                        pinned_pinned_axial_omega(b, 3)};
        double previous = 12.0;
        for (int m : {10, 20, 40}) {
            const double error = worst_frequency_error(bridge(m, ends, axial), exact);
            std::printf("pinned-pinned, sigma0 = %.4g MPa, m = %d: worst error of modes 1-3 %.2e\n", sigma / 1e6, m, error);
            // Hermite cubics: frequency errors fall like h^4 (16 times per halving).
            EXPECT_LT(error, previous / 12.0) << "converges with the mesh like h^4";
            previous = error;
        }
        EXPECT_LT(previous, 5e-6) << sigma;
    }
}

TEST(ResidualStress, ClampedClampedFrequenciesMatchTheCharacteristicEquation) {
    const std::string ends = "left = \"clamped\"\nright = \"clamped\"";
    for (const std::string axial : {"residual_stress = \"100 MPa\"", "residual_stress = \"-10 MPa\""}) {
        const AxialBeam b = reference_of(bridge(10, ends, axial));
        const std::vector<double> exact = clamped_clamped_axial_omegas(b, 3);
        double previous = 12.0;
        for (int m : {10, 20, 40}) {
            const double error = worst_frequency_error(bridge(m, ends, axial), exact);
            std::printf("clamped-clamped, %s, m = %d: worst error of modes 1-3 %.2e\n", axial.c_str(), m, error);
            // Hermite cubics: frequency errors fall like h^4 (16 times per halving).
            EXPECT_LT(error, previous / 12.0) << "converges with the mesh like h^4";
            previous = error;
        }
        EXPECT_LT(previous, 5e-6) << axial;
    }
    // The characteristic equation without axial force gives cosh(beta l) cos(beta l) = 1:
    // beta1 l = 4.730040745.
    AxialBeam b{1.0, 1.0, 1.0, 1.0, 0.0};
    EXPECT_NEAR(clamped_clamped_axial_omegas(b, 1)[0], 4.730040745 * 4.730040745, 1e-7);
}

TEST(MidplaneStretching, TangentAndEnergyAreTheForcesDerivatives) {
    // Three elements of a pinned-pinned beam: its G over v, theta of the free DOFs.
    const Case c = bridge(3, "left = \"pinned\"\nright = \"pinned\"", "stretching = true");
    const System s = build_system(c);
    const MidplaneStretching e("beam.stretching", submatrix(s.G, s.bending), 1e3);
    const std::size_t n = e.dofs().size();
    ASSERT_EQ(n, 6u);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst_tangent = 0.0, worst_energy = 0.0;
    for (int k = 0; k < 20; ++k) {
        std::vector<double> q(n), v(n, 0.0);
        for (std::size_t i = 0; i < n; ++i) q[i] = (s.free_dofs[s.bending[i]] % 3 == 1 ? 1e-6 : 1e-2) * u(rng);
        const auto force = [&](const std::vector<double>& x) {
            std::vector<double> f(n, 0.0);
            e.add_force(ElementState{0.0, x.data(), v.data(), nullptr}, 0, f.data());
            return f;
        };
        std::vector<double> dq(n * n, 0.0), dv(n * n, 0.0);
        e.add_tangent(ElementState{0.0, q.data(), v.data(), nullptr}, 0, dq.data(), dv.data());
        const std::vector<double> f = force(q);
        double scale = 0.0;
        for (double x : f) scale = std::max(scale, std::abs(x));
        for (std::size_t j = 0; j < n; ++j) {
            const double h = 1e-6 * std::abs(q[j]);
            std::vector<double> plus = q, minus = q;
            plus[j] += h;
            minus[j] -= h;
            const std::vector<double> fp = force(plus), fm = force(minus);
            for (std::size_t i = 0; i < n; ++i) {
                const double fd = (fp[i] - fm[i]) / (2 * h);
                worst_tangent = std::max(worst_tangent, std::abs(fd - dq[i * n + j]) * std::abs(q[j]) / scale);
            }
            const double dE = (e.stored_energy(ElementState{0.0, plus.data(), v.data(), nullptr}, 0) -
                               e.stored_energy(ElementState{0.0, minus.data(), v.data(), nullptr}, 0)) / (2 * h);
            worst_energy = std::max(worst_energy, std::abs(-dE - f[j]) / scale);
        }
        for (double x : dv) EXPECT_EQ(x, 0.0);
        EXPECT_EQ(e.dissipated_power(ElementState{0.0, q.data(), v.data(), nullptr}, 0), 0.0);
        EXPECT_EQ(e.input_power(ElementState{0.0, q.data(), v.data(), nullptr}, 0), 0.0);
    }
    EXPECT_LT(worst_tangent, 1e-8);
    EXPECT_LT(worst_energy, 1e-8);
    EXPECT_FALSE(e.linear_form().has_value());  // CVODE, never the exact solver
}

TEST(MidplaneStretching, AxialForceIsTheMeanSquareSlope) {
    // v = a sin(pi x / l) on a pinned-pinned beam: N = (E A / (2 l)) int v'^2 = E A a^2 pi^2 / (4 l^2).
    const Case c = bridge(40, "left = \"pinned\"\nright = \"pinned\"", "stretching = true");
    const System s = build_system(c);
    const double l = c.beam.length, a = 1e-6, pi = std::acos(-1.0), EA = s.props.E * s.props.A;
    const MidplaneStretching e("beam.stretching", submatrix(s.G, s.bending), EA / l);
    std::vector<double> q(s.bending.size());
    for (std::size_t i = 0; i < q.size(); ++i) {
        const int g = s.free_dofs[s.bending[i]];
        const double x = s.mesh.x[g / 3];
        q[i] = g % 3 == 1 ? a * std::sin(pi * x / l) : a * pi / l * std::cos(pi * x / l);
    }
    EXPECT_NEAR(e.axial_force(q.data()), EA * a * a * pi * pi / (4 * l * l), 1e-6 * EA * a * a * pi * pi / (4 * l * l));
}

TEST(BridgePullin, MatchesAnIndependentShootingSolution) {
    const std::string ends = "left = \"clamped\"\nright = \"clamped\"";
    struct Variant {
        std::string axial;
        bool stretching;
    };
    const std::vector<Variant> variants{{"", false},
                                        {"stretching = true", true},
                                        {"residual_stress = \"20 MPa\"", false},
                                        {"residual_stress = \"20 MPa\"\nstretching = true", true},
                                        {"residual_stress = \"-5 MPa\"\nstretching = true", true}};
    const auto one_line = [](std::string s) {
        std::replace(s.begin(), s.end(), '\n', ',');
        return s;
    };
    for (const Variant& v : variants) {
        const Case c10 = bridge(10, ends, v.axial);
        const BridgePullin ref = bridge_pullin_shooting(reference_of(c10), 3e-6, c10.beam.width, v.stretching);
        double previous = 12.0;
        for (int m : {10, 20, 40}) {
            const PullinResult r = trace_pullin(bridge(m, ends, v.axial));
            ASSERT_TRUE(r.pullin.has_value()) << r.end;
            const double error = std::abs(r.pullin->voltage / ref.voltage - 1.0);
            std::printf("bridge [%s] m = %d: V_PI = %.8g V (shooting %.8g V, mid-span %.4f g / %.4f g), error %.2e\n",
                        one_line(v.axial).c_str(), m, r.pullin->voltage, ref.voltage, r.pullin->watched_travel / 3e-6,
                        ref.mid_travel, error);
            EXPECT_LT(error, previous / 12.0) << v.axial << ": converges with the mesh like h^4";
            previous = error;
        }
        EXPECT_LT(previous, 1e-6) << v.axial;
    }
}

TEST(AxialInput, FreeEndsAndBucklingAreRefusedWithTheKey) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"left = \"clamped\"\nright = \"free\"\nresidual_stress = \"10 MPa\"", "beam.residual_stress: needs both ends"},
        {"left = \"clamped\"\nright = \"free\"\nstretching = true", "beam.stretching: needs both ends"},
        {"left = \"clamped\"\nright = \"clamped\"\nresidual_stress = \"-100 MPa\"", "beam.residual_stress: is a compression"},
        {"left = \"pinned\"\nright = \"pinned\"\nresidual_stress = \"-8 MPa\"", "buckles at -7.31082e+06 Pa"},
        {"left = \"clamped\"\nright = \"clamped\"\nresidual_stress = \"10 m\"", "beam.residual_stress"},
    };
    for (const auto& [keys, expected] : cases) {
        try {
            (void)bridge(10, "", keys);
            ADD_FAILURE() << "accepted: " << keys;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).rfind("bridge.toml:", 0), 0u) << e.what();
        }
    }
    // Just below buckling is accepted and K stays positive definite (the FE model buckles above Euler).
    const Case c = bridge(10, "left = \"pinned\"\nright = \"pinned\"", "residual_stress = \"-7.3 MPa\"");
    EXPECT_GT(analyse_modes(build_system(c), 1).bending[0].omega, 0.0);
}


// The bridge switch example: pull-in from the command line (stretching and residual stress raise it
// from the bare bridge's), and a step to 1.2 V_PI that closes the switch with the energy ledger
// (kinetic + strain + stretching + contact springs - C V^2/2 + dissipated) constant to 1e-6 of the
// electrical energy.
TEST(BridgeSwitchExample, PullinAndAClosingTransientWithItsEnergyBalance) {
    const std::string file = test::source_path("examples/switch/bridge_switch.toml");
    const auto r = test::run_vibroimpact({"pullin", file, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const double v_pi = j["pullin"]["voltage_V"].get<double>();
    EXPECT_GT(v_pi, 55.0);
    EXPECT_LT(v_pi, 61.0);
    EXPECT_LT(j["release_voltage_V"].get<double>(), v_pi);

    const Case c = read_case_file(file);
    Case bare = c;
    bare.beam.stretching = false;
    bare.beam.residual_stress = 0.0;
    const PullinResult b = trace_pullin(bare);
    ASSERT_TRUE(b.pullin.has_value());
    std::printf("bridge example: V_PI %.4f V, without stretching and residual stress %.4f V\n", v_pi, b.pullin->voltage);
    EXPECT_GT(v_pi, 1.5 * b.pullin->voltage);

    const BuiltProblem built = build_transient_problem(c);
    CvodeOptions o;
    o.rtol = 1e-9;  // at the example's 1e-8 the ledger drifts by 1.3e-6
    const TransientResult t = solve_cvode(built.problem, o);
    ASSERT_FALSE(t.episodes.empty());
    const auto total = [](const EnergyLedger& e) {
        return e.kinetic + e.strain + e.contact_spring + e.electrical + e.contact_dissipated + e.rayleigh_dissipated -
               e.external_work;
    };
    // The electrode's energy at the start, -C V^2 / 2 (the stretching's, in strain, is zero at rest).
    const double electrical = std::abs(t.initial_energy.electrical);
    const double drift = std::abs(total(t.final_energy) - total(t.initial_energy)) / electrical;
    std::printf("bridge example: first contact %.4g us, %zu episodes, ledger drift %.2e of C V^2/2\n",
                t.episodes.front().t_on * 1e6, t.episodes.size(), drift);
    EXPECT_LT(drift, 1e-6);
    EXPECT_GT(t.episodes.front().t_on, 1e-6);
    EXPECT_TRUE(t.episodes.back().closed_at_end);
}

}  // namespace
}  // namespace vi
