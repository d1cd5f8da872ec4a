// The beam landing on an electrode's dielectric layer (forces/dielectric_contact.hpp): the element's
// contract, the landed equilibria of a rigid plate against their closed form, and a capacitive
// switch's landing transient with its energy ledger.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "statics/pullin.hpp"
#include "forces/dielectric_contact.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "support/pad_points.hpp"
#include "validation/electrostatic_references.hpp"

namespace vi {
namespace {

// A layer 0.2 um thick on an electrode 2 um above the beam's axis (its face 1.8 um above), over [0, to].
PadGeometry layer_geometry(double to) {
    PadGeometry geo;
    geo.sign = 1.0;
    geo.gap = 2e-6;
    geo.dielectric_thickness = 0.2e-6;
    geo.dielectric_permittivity = 7.5;
    geo.width = 30e-6;
    geo.to = to;
    return geo;
}

// That layer above one beam element of length 10 um.
DielectricContact layer_on_element(double stiffness) {
    const double L = 10e-6;
    return DielectricContact("electrodes[0].dielectric", {0, 1, 2, 3}, test::one_element_points(L), layer_geometry(L), stiffness);
}

TEST(DielectricContact, TangentAndEnergyMatchTheForceAndItSwitchesAtTheFace) {
    const DielectricContact c = layer_on_element(3.75e10);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<double> v(4, 0.0);
    int pressed = 0;
    for (int k = 0; k < 20; ++k) {
        // Around the face (1.8 um up): some points pressing into the layer, some not.
        std::vector<double> q{1.8e-6 + 2e-9 * u(rng), 4e-4 * u(rng), 1.8e-6 + 2e-9 * u(rng), 4e-4 * u(rng)};
        const ElementState s{0.0, q.data(), v.data(), nullptr};
        const double d = c.contact_reading(s).penetration;
        EXPECT_EQ(c.static_mode(s), d > 1e-12 * 2e-6 ? 1 : 0);
        EXPECT_EQ(c.switching_function(s, 0) > 0.0, d > 0.0);
        if (d <= 0.0) {
            std::vector<double> f(4, 0.0);
            c.add_force(s, 1, f.data());
            for (double x : f) EXPECT_EQ(x, 0.0);
            continue;
        }
        ++pressed;
        const auto force = [&](const std::vector<double>& x) {
            std::vector<double> f(4, 0.0);
            c.add_force(ElementState{0.0, x.data(), v.data(), nullptr}, 1, f.data());
            return f;
        };
        std::vector<double> dq(16, 0.0), dv(16, 0.0);
        c.add_tangent(s, 1, dq.data(), dv.data());
        const std::vector<double> f = force(q);
        // It pushes the beam back, down, away from the electrode above: the force on v is negative.
        EXPECT_LT(f[0] + f[2], 0.0);
        for (int j = 0; j < 4; ++j) {
            const double h = (j % 2 == 0 ? 1e-14 : 1e-9);
            std::vector<double> p = q, m = q;
            p[j] += h;
            m[j] -= h;
            const std::vector<double> fp = force(p), fm = force(m);
            for (int i = 0; i < 4; ++i) {
                const double fd = (fp[i] - fm[i]) / (2 * h);
                EXPECT_NEAR(dq[i * 4 + j], fd, 1e-5 * std::abs(fd) + 1e-6 * std::abs(dq[i * 4 + j]) + 1e-30);
            }
            const double de = (c.stored_energy(ElementState{0.0, p.data(), v.data(), nullptr}, 1) -
                               c.stored_energy(ElementState{0.0, m.data(), v.data(), nullptr}, 1)) /
                              (2 * h);
            EXPECT_NEAR(-de, f[j], 1e-5 * std::abs(f[j]) + 1e-20);
        }
    }
    EXPECT_GT(pressed, 3);  // the draw pressed into the layer often enough to test something
}

// A rigid plate (mass on a spring k) under an electrode with a dielectric: after pull-in it lands on
// the layer (touch-down where k x = eps0 A V^2 / (2 (t_d / eps_r)^2) at x = the air gap) and the
// landed equilibria satisfy k x + k_d L (x - g_a) = eps0 A V^2 / (2 (g_a - x + t_d / eps_r)^2).
// The reading's parts given alone are its own numbers to the last bit, with each element's DOFs
// gathered once (a layer over a clamped element, whose held DOFs are no entries, and the next one),
// elastic and adhesive: the deepest point, its velocity and the force as one point at a time gives them.
TEST(DielectricContact, ItsForceAndPointVelocityAloneAreItsReadingsBitForBit) {
    const double L = 10e-6;
    std::vector<PadPoint> pts = test::one_element_points(L);
    for (PadPoint& p : pts) p.local = {-1, -1, 0, 1};
    for (PadPoint p : test::one_element_points(L)) {
        p.x += L;
        pts.push_back(p);
    }
    const PadGeometry geo = layer_geometry(2 * L);
    const double k = 3.75e10;
    const DielectricContact elastic("elastic", {0, 1, 2, 3}, pts, geo, k);
    const DielectricContact adhesive("adhesive", {0, 1, 2, 3}, pts, geo, AdhesiveLayerLaw(k, 1e-3, 5e-9));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int n = 0; n < 200; ++n) {
        const std::vector<double> q{1.8e-6 + 4e-9 * u(rng), 4e-4 * u(rng), 1.8e-6 + 4e-9 * u(rng), 4e-4 * u(rng)};
        const std::vector<double> v{u(rng), 1e5 * u(rng), u(rng), 1e5 * u(rng)};
        const ElementState s{0.0, q.data(), v.data(), nullptr};
        for (const DielectricContact* c : {&elastic, &adhesive}) {
            std::size_t deepest = 0;
            double force = 0.0;
            for (std::size_t i = 0; i < pts.size(); ++i) {
                const double d = c->penetration(pts[i], q.data());
                if (d > c->penetration(pts[deepest], q.data())) deepest = i;
                if (c->adhesion()) {
                    force += c->adhesion()->at(d).force * pts[i].weight;
                } else if (d > 0.0) {
                    force += k * d * pts[i].weight;
                }
            }
            const ContactReading r = c->contact_reading(s);
            EXPECT_EQ(r.penetration, c->penetration(pts[deepest], q.data()));
            EXPECT_EQ(r.point_velocity, point_displacement(pts[deepest], v.data()));
            EXPECT_EQ(r.force, force);
            EXPECT_EQ(c->contact_force(s), force);
            EXPECT_EQ(c->contact_point_velocity(s), r.point_velocity);
        }
    }
}

TEST(DielectricContact, ARigidPlateLandsWhereTheClosedFormSays) {
    const double k = 2.0, mass = 1e-11, gap = 2e-6, width = 30e-6, length = 100e-6, td = 0.2e-6, er = 7.5, E = 250e9;
    PullinModel m = parallel_plate_model(k, mass, gap, width, length);
    // The layer on the same point as the pad.
    PadGeometry geo = m.pads.front()->geometry();
    geo.dielectric_thickness = td;
    geo.dielectric_permittivity = er;
    PadPoint p;
    p.x = 0.5 * length;
    p.weight = length;
    p.local = {0, -1, -1, -1};
    p.shape = {1.0, 0.0, 0.0, 0.0};
    m.pads = {std::make_shared<const ElectrostaticPad>("electrodes[0]", std::vector<int>{0}, std::vector<PadPoint>{p}, geo,
                                                       1.0, TimeFunction{})};
    const double kd = E * width / td;
    m.contacts = {std::make_shared<const DielectricContact>("electrodes[0].dielectric", std::vector<int>{0},
                                                            std::vector<PadPoint>{p}, geo, kd)};
    const double air = gap - td, g_e0 = air + td / er;
    m.air_gap = air;
    const PullinResult r = trace_pullin(m);
    const double area = width * length;
    ASSERT_TRUE(r.pullin.has_value());
    EXPECT_NEAR(r.pullin->voltage, std::sqrt(8 * k * g_e0 * g_e0 * g_e0 / (27 * kEpsilon0 * area)), 1e-9 * r.pullin->voltage);
    ASSERT_TRUE(r.touchdown.has_value());
    const double v_td = std::sqrt(2 * k * air * (td / er) * (td / er) / (kEpsilon0 * area));
    EXPECT_NEAR(r.touchdown->voltage, v_td, 1e-9 * v_td);
    int landed = 0;
    for (const PullinPoint& x : r.branch) {
        if (!x.contact) continue;
        ++landed;
        const double travel = x.travel;  // toward the electrode = -v
        const double lhs = k * travel + kd * length * (travel - air);
        const double rhs = kEpsilon0 * area * x.voltage * x.voltage / (2 * std::pow(air - travel + td / er, 2));
        EXPECT_NEAR(lhs, rhs, 1e-8 * rhs);
        EXPECT_NEAR(x.contact_force, kd * length * (travel - air), 1e-8 * x.contact_force + 1e-20);
    }
    EXPECT_GT(landed, 0);
}

// A capacitive cantilever switch (no support; a nitride layer on the electrode) stepped to 70 V
// lands on the layer, bounces and stays; no damping, so the ledger (kinetic + strain + layer +
// electrical - source work) stays constant.
TEST(DielectricContact, ACapacitiveSwitchLandsWithItsEnergyBalance) {
    Case c = read_case_text(R"(
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
from = 0.1
to = 1.0
gap = "2 um"
dielectric_thickness = "0.2 um"
dielectric_permittivity = 7.5
voltage = "70 V"
waveform = "step"
[initial]
kind = "rest"
[solver]
method = "cvode"
horizon = "3 us"
rtol = 1e-9
)",
                            "capacitive.toml");
    const BuiltProblem b = build_transient_problem(c);
    CvodeOptions o;
    o.rtol = 1e-9;
    const TransientResult t = solve_cvode(b.problem, {}, o);
    ASSERT_FALSE(t.episodes.empty());
    EXPECT_GT(t.episodes.front().t_on, 1e-6);
    EXPECT_LT(t.episodes.front().v_in, 0.0);  // it lands moving down
    const auto total = [](const EnergyLedger& e) {
        return e.kinetic + e.strain + e.contact_spring + e.electrical + e.rayleigh_dissipated + e.contact_dissipated -
               e.external_work;
    };
    const double scale = std::abs(t.final_energy.electrical);
    EXPECT_LT(std::abs(total(t.final_energy) - total(t.initial_energy)), 1e-6 * scale);
    std::printf("capacitive switch: lands at %.4g us at %.3g m/s, %zu episodes, ledger drift %.2e of C V^2/2 at the end\n",
                t.episodes.front().t_on * 1e6, t.episodes.front().v_in, t.episodes.size(),
                std::abs(total(t.final_energy) - total(t.initial_energy)) / scale);
}

TEST(DielectricContact, ItsModulusIsCheckedWithItsKey) {
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
from = 0.1
to = 1.0
gap = "2 um"
voltage = "5 V"
)";
    for (const auto& [body, expected] :
         std::vector<std::pair<std::string, std::string>>{{"dielectric_modulus = \"100 GPa\"\n", "needs dielectric_thickness"},
                                                          {"dielectric_thickness = \"0.2 um\"\ndielectric_modulus = \"0 GPa\"\n",
                                                           "electrodes[0].dielectric_modulus: must be positive"}}) {
        try {
            (void)read_case_text(base + body, "bad.toml");
            ADD_FAILURE() << body;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace vi
