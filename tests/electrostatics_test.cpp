// Electrostatic actuation (docs/electrostatics.md): the pad element's contract, the one-degree-of-
// freedom parallel plate against its closed forms, the cantilever's pull-in against an independent
// shooting solution of the beam equation, the energy balance of a switching transient, and the
// case reader's refusals.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "statics/pullin.hpp"
#include "forces/electrostatic_pad.hpp"
#include "forces/kelvin_voigt_contact.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "support/pad_points.hpp"
#include "support/run_command.hpp"
#include "validation/electrostatic_references.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

// A pad over one beam element of length 10 um (4 DOFs), with a dielectric and Meijs-Fokkema fringing.
std::shared_ptr<const ElectrostaticPad> beam_pad(Fringing fringing, TimeFunction g) {
    const double L = 10e-6;
    const std::vector<PadPoint> pts = test::one_element_points(L);
    PadGeometry geo;
    geo.sign = 1.0;
    geo.gap = 2e-6;
    geo.dielectric_thickness = 0.2e-6;
    geo.dielectric_permittivity = 7.5;
    geo.width = 30e-6;
    geo.beam_thickness = 2e-6;
    geo.fringing = fringing;
    geo.to = L;
    return std::make_shared<const ElectrostaticPad>("electrodes[1]", std::vector<int>{0, 1, 2, 3}, pts, geo, 40.0, g);
}

TEST(ElectrostaticPad, TangentEnergyAndPowerMatchTheForce) {
    TimeFunction ramp;
    ramp.kind = TimeFunction::Kind::table;
    ramp.times = {0.0, 1e-5};
    ramp.values = {0.2, 1.0};
    for (Fringing fr : {Fringing::none, Fringing::meijs_fokkema}) {
        const auto pad = beam_pad(fr, ramp);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int k = 0; k < 10; ++k) {
            const double t = 5e-6 * (1 + u(rng));
            std::vector<double> q{0.5e-6 * u(rng), 0.02 * u(rng), 0.5e-6 * u(rng), 0.02 * u(rng)};
            std::vector<double> v{0.3 * u(rng), 1e4 * u(rng), 0.3 * u(rng), 1e4 * u(rng)};
            const auto force = [&](const std::vector<double>& x) {
                std::vector<double> f(4, 0.0);
                pad->add_force(ElementState{t, x.data(), v.data(), nullptr}, 0, f.data());
                return f;
            };
            const auto energy = [&](const std::vector<double>& x) {
                return pad->stored_energy(ElementState{t, x.data(), v.data(), nullptr}, 0);
            };
            std::vector<double> dq(16, 0.0), dv(16, 0.0);
            pad->add_tangent(ElementState{t, q.data(), v.data(), nullptr}, 0, dq.data(), dv.data());
            const std::vector<double> f = force(q);
            double power = 0.0;
            for (int j = 0; j < 4; ++j) {
                const double h = (j % 2 == 0 ? 1e-12 : 1e-7);
                std::vector<double> p = q, m = q;
                p[j] += h;
                m[j] -= h;
                const std::vector<double> fp = force(p), fm = force(m);
                for (int i = 0; i < 4; ++i) {
                    const double fd = (fp[i] - fm[i]) / (2 * h);
                    EXPECT_NEAR(dq[i * 4 + j], fd, 1e-6 * std::abs(fd) + 1e-12 * std::abs(dq[i * 4 + j]) + 1e-30);
                }
                // The stored energy (minus the co-energy) is the potential of the force.
                EXPECT_NEAR(-(energy(p) - energy(m)) / (2 * h), f[j], 1e-6 * std::abs(f[j]) + 1e-25);
                power += f[j] * v[j];
            }
            EXPECT_EQ(pad->dissipated_power(ElementState{t, q.data(), v.data(), nullptr}, 0), 0.0);
            // d/dt of the stored energy along a motion is -f.v plus the source term -C V dV/dt.
            const double dt = 1e-13;
            std::vector<double> qp = q, qm = q;
            for (int i = 0; i < 4; ++i) {
                qp[i] += v[i] * dt;
                qm[i] -= v[i] * dt;
            }
            const double dE = (pad->stored_energy(ElementState{t + dt, qp.data(), v.data(), nullptr}, 0) -
                               pad->stored_energy(ElementState{t - dt, qm.data(), v.data(), nullptr}, 0)) /
                              (2 * dt);
            const double input = pad->input_power(ElementState{t, q.data(), v.data(), nullptr}, 0);
            EXPECT_NEAR(dE, -power + input, 1e-6 * (std::abs(power) + std::abs(input)));
        }
    }
}

// The parallel plate on a spring k: V_PI = sqrt(8 k g^3 / (27 eps0 A)) at a travel of g/3
// (e.g. Senturia, Microsystem Design, 2001, §6.4).
TEST(ElectrostaticPullin, OneDegreeOfFreedomPlateMatchesTheClosedForm) {
    const double k = 2.0, g = 2e-6, w = 100e-6, L = 100e-6;
    const PullinModel m = parallel_plate_model(k, 1e-10, g, w, L);
    const PullinResult r = trace_pullin(m);
    ASSERT_TRUE(r.pullin.has_value()) << r.end;
    const double v_pi = std::sqrt(8.0 * k * g * g * g / (27.0 * kEpsilon0 * w * L));
    EXPECT_NEAR(r.pullin->voltage / v_pi - 1.0, 0.0, 1e-6);
    EXPECT_NEAR(r.pullin->travel / (g / 3.0) - 1.0, 0.0, 1e-6);
    // Along the branch every point satisfies k x = eps0 A V^2 / (2 (g - x)^2) and C = eps0 A / (g - x);
    // stable exactly below the fold.
    for (const PullinPoint& p : r.branch) {
        const double x = p.travel;
        EXPECT_NEAR(k * x, kEpsilon0 * w * L * p.voltage * p.voltage / (2 * (g - x) * (g - x)), 1e-9 * k * g);
        EXPECT_NEAR(p.capacitance, kEpsilon0 * w * L / (g - x), 1e-12 * p.capacitance);
        if (std::abs(x - g / 3) > 1e-3 * g) {
            EXPECT_EQ(p.stable, x < g / 3) << x;
        }
    }
    // Electrostatic softening: omega^2 = (k - eps0 A V^2 / g_x^3) / m at the equilibrium.
    ASSERT_FALSE(r.frequencies.empty());
    for (const PullinFrequencies& f : r.frequencies) {
        ASSERT_EQ(f.frequency_hz.size(), 1u);
        const double V = f.voltage;
        // Solve k x (g - x)^2 = eps0 A V^2 / 2 for the stable root by bisection on [0, g/3].
        double lo = 0.0, hi = g / 3.0;
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            (k * mid * (g - mid) * (g - mid) < kEpsilon0 * w * L * V * V / 2 ? lo : hi) = mid;
        }
        const double gx = g - lo;
        const double omega2 = (k - kEpsilon0 * w * L * V * V / (gx * gx * gx)) / 1e-10;
        if (omega2 > 1e-3 * k / 1e-10) {
            EXPECT_NEAR(f.frequency_hz[0], std::sqrt(omega2) / (2 * M_PI), 1e-6 * f.frequency_hz[0]);
        }
    }
}

Case cantilever_case(int elements) {
    return read_case_text(R"(
[beam]
length = "117 um"
width = "30 um"
thickness = "2 um"
elements = )" + std::to_string(elements) + R"(
left = "clamped"
right = "free"
[material]
youngs_modulus = "207 GPa"
density = "8902 kg/m^3"
poisson_ratio = 0.31
[[electrodes]]
from = 0.0
to = 1.0
gap = "2 um"
voltage = "1 V"
)",
                          "cantilever.toml");
}

TEST(ElectrostaticPullin, CantileverMatchesAnIndependentShootingSolution) {
    const double lambda = cantilever_pullin_lambda_shooting();
    const Case c = cantilever_case(10);
    const double EI = c.material.effective_modulus() * c.beam.second_moment(), g = 2e-6, l = c.beam.length;
    double previous = 1.0;
    for (int m : {5, 10, 20, 40}) {
        const PullinResult r = trace_pullin(cantilever_case(m));
        ASSERT_TRUE(r.pullin.has_value()) << r.end;
        const double fe = kEpsilon0 * c.beam.width * r.pullin->voltage * r.pullin->voltage * l * l * l * l / (2 * EI * g * g * g);
        const double error = std::abs(fe / lambda - 1.0);
        std::printf("m = %d: lambda_PI = %.10f (shooting %.10f), relative error %.2e, tip travel %.4f g\n", m, fe, lambda,
                    error, r.pullin->watched_travel / g);
        EXPECT_LT(error, previous) << "the FE value converges with the mesh";
        previous = error;
    }
    EXPECT_LT(previous, 1e-6);
}

TEST(ElectrodeInput, BadValuesAreRefusedWithTheirKey) {
    const std::string base = R"(
[beam]
length = "117 um"
width = "30 um"
thickness = "2 um"
elements = 10
[material]
youngs_modulus = "207 GPa"
density = "8902 kg/m^3"
poisson_ratio = 0.31
[[electrodes]]
)";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"from = 0.2\nto = 0.8\ngap = \"0 um\"\nvoltage = \"5 V\"\n", "electrodes[0].gap: must be positive"},
        {"from = 0.5\nto = 0.5\ngap = \"1 um\"\nvoltage = \"5 V\"\n", "electrodes[0].to: must be greater than from"},
        {"from = 0.2\nto = 1.2\ngap = \"1 um\"\nvoltage = \"5 V\"\n", "electrodes[0].to: must lie in (0, 1]"},
        {"from = 0.2\nto = 0.8\ngap = \"1 um\"\ndielectric_thickness = \"1 um\"\nvoltage = \"5 V\"\n",
         "electrodes[0].dielectric_thickness: must be smaller than the gap"},
        {"from = 0.2\nto = 0.8\ngap = \"1 um\"\nvoltage = \"5 m\"\n", "electrodes[0].voltage"},
        {"from = 0.2\nto = 0.8\ngap = \"1 um\"\nvoltage = \"5 V\"\nwaveform = \"pulse\"\nrise = \"1 us\"\nhold = \"2 us\"\n",
         "electrodes[0].fall"},
        {"from = 0.2\nto = 0.8\ngap = \"1 um\"\nvoltage = \"5 V\"\nrise = \"1 us\"\n", "only with"},
        // w/g = 30 um / 0.5 um = 60: outside the range Meijs and Fokkema state their formula for.
        {"from = 0.2\nto = 0.8\ngap = \"0.5 um\"\nvoltage = \"5 V\"\nfringing = \"meijs-fokkema\"\n",
         "electrodes[0].fringing: \"meijs-fokkema\" holds for 0.3 <= w/g <= 30"},
    };
    // Inside the range (w/g = 15, t/g = 1) it is taken.
    EXPECT_NO_THROW((void)read_case_text(base + "from = 0.2\nto = 0.8\ngap = \"2 um\"\nvoltage = \"5 V\"\n"
                                                "fringing = \"meijs-fokkema\"\n", "good.toml"));
    for (const auto& [body, expected] : cases) {
        try {
            (void)read_case_text(base + body, "bad.toml");
            ADD_FAILURE() << "accepted: " << body;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).rfind("bad.toml:", 0), 0u) << e.what();
        }
    }
}

// The switch example: pull-in from the command line, and a step to 1.2 V_PI closing the switch with
// the energy ledger (kinetic + strain + contact springs - C V^2/2 + dissipated) constant to 1e-6
// of the electrical energy.
TEST(SwitchExample, PullinAndAClosingTransientWithItsEnergyBalance) {
    const std::string file = test::source_path("examples/switch/cantilever_switch.toml");
    const auto r = test::run_vibroimpact({"pullin", file, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const double v_pi = j["pullin"]["voltage_V"].get<double>();
    EXPECT_GT(v_pi, 50.0);
    EXPECT_LT(v_pi, 70.0);
    EXPECT_LT(j["release_voltage_V"].get<double>(), v_pi);  // the closed switch holds below V_PI

    const BuiltProblem b = build_transient_problem(read_case_file(file));
    CvodeOptions o;
    o.rtol = 1e-8;
    const TransientResult t = solve_cvode(b.problem, o);
    ASSERT_FALSE(t.episodes.empty());
    const auto total = [](const EnergyLedger& e) {
        return e.kinetic + e.strain + e.contact_spring + e.electrical + e.contact_dissipated + e.rayleigh_dissipated -
               e.external_work;
    };
    // The electrode's energy is in its own term, not among the contact springs.
    EXPECT_EQ(t.initial_energy.contact_spring, 0.0);
    EXPECT_LT(t.initial_energy.electrical, 0.0);
    const double electrical = std::abs(t.initial_energy.electrical);
    EXPECT_LT(std::abs(total(t.final_energy) - total(t.initial_energy)), 1e-6 * electrical);
    // It closes: the first contact comes after the flight across the 1.5 um gap, and the last
    // episode lasts to the end (closed while the voltage holds).
    EXPECT_GT(t.episodes.front().t_on, 1e-6);
    EXPECT_TRUE(t.episodes.back().closed_at_end);
}

}  // namespace
}  // namespace vi
