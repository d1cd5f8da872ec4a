// Adhesion on an electrode's dielectric layer (docs/adhesion.md §9-10): the law's one energy and its
// well depth, the contact's switching rules, the S-shaped stuck cantilever lying on the layer against
// its semi-analytic solution and the closed form of the stiction literature, the energy ledger of a
// switch that lands and sticks or lets go, the peel balance of the stiction check, and the case keys.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_solver.hpp"
#include "statics/layer_hold.hpp"
#include "dynamics/transient_start.hpp"
#include "statics/static_minimum.hpp"
#include "forces/adhesive_layer_law.hpp"
#include "forces/dielectric_contact.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "study/stiction/stiction.hpp"
#include "support/pad_points.hpp"

namespace vi {
namespace {

// phi(d) by 20-point Gauss-Legendre quadrature of f from -r, piece by piece (the law's pieces are
// polynomials of degree <= 3, so this is exact to rounding).
double integrated_energy(const AdhesiveLayerLaw& law, double d) {
    static const double x[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195, 0.5108670019508271,
                                 0.6360536807265150, 0.7463319064601508, 0.8391169718222188, 0.9122344282513259,
                                 0.9639719272779138, 0.9931285991850949};
    static const double w[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183820, 0.1316886384491766,
                                 0.1181945319615184, 0.1019301198172404, 0.0832767415767048, 0.0626720483341091,
                                 0.0406014298003869, 0.0176140071391521};
    const double r = law.range();
    std::vector<double> knots{-r};
    for (double k : {0.0, r}) {
        if (k < d) knots.push_back(k);
    }
    knots.push_back(d);
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
        const double a = knots[i], b = knots[i + 1], mid = 0.5 * (a + b), half = 0.5 * (b - a);
        for (int j = 0; j < 10; ++j) {
            sum += half * w[j] * (law.at(mid + half * x[j]).force + law.at(mid - half * x[j]).force);
        }
    }
    return sum;
}

// Both regimes of the law: the rest inside the part where the layer's stiffness comes in (d_0 < r:
// a stiff layer, a weak adhesion) and beyond it (d_0 > r), and the paper's beam on nitride.
TEST(AdhesiveLayerLaw, OneEnergyWhoseWellIsTheAdhesionEnergy) {
    struct P {
        double k, W, r;
    };
    for (const P& p : {P{3.75e13, 3e-6, 2e-9}, P{1e3, 0.1 * 1e3 * 0.09e-12, 0.3e-6}, P{1e3, 5.0 * 1e3 * 0.04e-12, 0.2e-6},
                       P{1e10, 1e-3, 1e-9}}) {
        const AdhesiveLayerLaw law(p.k, p.W, p.r);
        const double d0 = law.rest_penetration(), q = law.largest_pull();
        // The rest: no force, energy -W (the work of adhesion per unit length), a minimum.
        EXPECT_NEAR(law.at(d0).force, 0.0, 1e-12 * q);
        EXPECT_NEAR(law.at(d0).energy, -p.W, 1e-12 * p.W);
        EXPECT_GT(law.at(d0).slope, 0.0);
        // The largest pull q is at the face.
        EXPECT_DOUBLE_EQ(law.at(0.0).force, -q);
        // Out of range: nothing at all.
        const AdhesiveLayerLaw::Value out = law.at(-p.r * (1.0 + 1e-12));
        EXPECT_EQ(out.force, 0.0);
        EXPECT_EQ(out.slope, 0.0);
        EXPECT_EQ(out.energy, 0.0);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1.5, 3.0 + 3.0 * d0 / p.r);
        double worst_energy = 0.0, worst_least = 0.0;
        for (int i = 0; i < 200; ++i) {
            const double d = p.r * u(rng);
            const AdhesiveLayerLaw::Value v = law.at(d);
            // phi is the integral of f from the end of the range, and nowhere below -W.
            worst_energy = std::max(worst_energy, std::abs(v.energy - integrated_energy(law, d)) / p.W);
            worst_least = std::max(worst_least, (-p.W - v.energy) / p.W);
            // f' by central differences.
            const double h = 1e-7 * p.r;
            EXPECT_NEAR(v.slope, (law.at(d + h).force - law.at(d - h).force) / (2 * h), 1e-5 * (std::abs(v.slope) + q / p.r));
        }
        EXPECT_LT(worst_energy, 1e-12);
        EXPECT_LT(worst_least, 1e-12);
        // C1 at the knots: the force and its slope meet from both sides.
        for (double knot : {-p.r, 0.0, p.r}) {
            const double e = 1e-9 * p.r;
            EXPECT_NEAR(law.at(knot - e).force, law.at(knot + e).force, 1e-6 * q) << knot;
            EXPECT_NEAR(law.at(knot - e).slope, law.at(knot + e).slope, 1e-6 * (q / p.r + p.k)) << knot;
        }
        std::printf("k %.3g N/m^2, W %.3g J/m, r %.3g m: q %.6g N/m, d_0 %.6g m (d_0 / r = %.4g)\n", p.k, p.W, p.r, q, d0,
                    d0 / p.r);
    }
    // The limits: a rigid layer makes the attraction carry W alone, q -> 2 W / r (a smoothstep's mean
    // is 1/2); a vanishing range makes the layer's spring carry it, q -> sqrt(2 k W).
    const double W = 3e-6, r = 2e-9, k = 3.75e13;
    EXPECT_NEAR(AdhesiveLayerLaw(1e30, W, r).largest_pull(), 2.0 * W / r, 1e-6 * 2.0 * W / r);
    EXPECT_NEAR(AdhesiveLayerLaw(k, W, 1e-18).largest_pull(), std::sqrt(2.0 * k * W), 1e-6 * std::sqrt(2.0 * k * W));
}

// A layer on one element 10 um long, its face 1.8 um above the axis.
DielectricContact layer_above(const AdhesiveLayerLaw& law) {
    PadGeometry g;
    g.sign = 1.0;
    g.gap = 2e-6;
    g.dielectric_thickness = 0.2e-6;
    g.dielectric_permittivity = 7.5;
    g.width = 30e-6;
    g.to = 10e-6;
    return DielectricContact("electrodes[0].dielectric", {0, 1, 2, 3}, test::one_element_points(10e-6), g, law);
}

// Closed from the moment a point presses into the face until the last point leaves the range (not
// at each sub-nm vibration of a held beam about the face); the force is the law's in both modes.
TEST(DielectricAdhesion, TheContactHoldsUntilTheBeamLeavesTheRange) {
    const double r = 2e-9;
    const DielectricContact c = layer_above(AdhesiveLayerLaw(3.75e13, 3e-6, r));
    EXPECT_EQ(c.kind(), "adhesive dielectric contact");
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<double> v(4, 0.0);
    for (int k = 0; k < 200; ++k) {
        // Flat within a few nm of the face, tilted a little.
        const double z = 1.8e-6 + 3e-9 * u(rng);
        const std::vector<double> q{z, 1e-4 * u(rng), z + 1e-9 * u(rng), 1e-4 * u(rng)};
        const ElementState s{0.0, q.data(), v.data(), nullptr};
        const double d = c.contact_reading(s).penetration;
        EXPECT_EQ(c.switching_function(s, 0) > 0.0, d > 0.0);
        EXPECT_EQ(c.switching_function(s, 1) > 0.0, d < -r);
        std::vector<double> f0(4, 0.0), f1(4, 0.0);
        c.add_force(s, 0, f0.data());
        c.add_force(s, 1, f1.data());
        EXPECT_EQ(f0, f1);
        EXPECT_EQ(c.stored_energy(s, 0), c.stored_energy(s, 1));
    }
    // Resting at the law's rest, every point pulls and pushes to nothing; lifted to the face, it pulls.
    const AdhesiveLayerLaw law(3.75e13, 3e-6, r);
    const double rest = 1.8e-6 + law.rest_penetration();
    std::vector<double> q{rest, 0.0, rest, 0.0};
    EXPECT_NEAR(c.contact_reading(ElementState{0.0, q.data(), v.data(), nullptr}).force, 0.0, 1e-9 * law.largest_pull() * 10e-6);
    q = {1.8e-6, 0.0, 1.8e-6, 0.0};
    EXPECT_NEAR(c.contact_reading(ElementState{0.0, q.data(), v.data(), nullptr}).force, -law.largest_pull() * 10e-6,
                1e-9 * law.largest_pull() * 10e-6);
    EXPECT_NEAR(c.stored_energy(ElementState{0.0, q.data(), v.data(), nullptr}, 1), -0.5 * law.largest_pull() * r * 10e-6,
                1e-9 * 3e-6 * 10e-6);
}

// A nickel cantilever (207 GPa, 30 x 2 um) lying on a nitride layer (0.2 um, 250 GPa) under its whole
// length, 1.8 um below its axis, w = 0.1 J/m^2, no voltage.
std::string lying_case(int elements, double range_m) {
    char buf[1024];
    std::snprintf(buf, sizeof buf, R"(
[beam]
length = "150 um"
width = "30 um"
thickness = "2 um"
elements = %d
[material]
youngs_modulus = "207 GPa"
density = "8902 kg/m^3"
poisson_ratio = 0.31
[[electrodes]]
from = 0.0
to = 1.0
gap = "2 um"
dielectric_thickness = "0.2 um"
work_of_adhesion = "0.1 J/m^2"
adhesion_range = "%.17g m"
voltage = "0 V"
[solver]
method = "cvode"
)",
                  elements, range_m);
    return buf;
}

// Laid flat on the layer from x = start on, the beam settles downhill; where it first touches.
double settled_detached_length(const Case& c, double start) {
    const BuiltProblem b = build_transient_problem(c);
    const double h = c.electrodes[0].gap - c.electrodes[0].dielectric_thickness;
    const Eigen::VectorXd q0 = held_flat(b.model.system, b.problem.K, start, c.beam.length, -h);
    const StaticState s =
        minimize_static_energy(b.problem.K, b.problem.forces, Eigen::VectorXd::Zero(q0.size()), q0, 500);
    const auto contact = layer_contact(c, 0, b.model.system, s.q);
    return contact ? contact->first : -1.0;
}

// The S-shaped stuck cantilever: the FE beam lying on the layer, settled from either side of the
// answer, against the semi-analytic solution of the same beam on the layer's zero-range limit
// (study/stiction: detached_length_on_layer), which lies 1 / (b l_d) = 0.86 % short of the rigid
// closed form l_d = (3 E t^3 h^2 / (2 w))^(1/4) (Mastrangelo & Hsu 1993).
TEST(DielectricAdhesion, TheStuckCantileverDetachesWhereTheEnergyBalanceSays) {
    const double E = 207e9, t = 2e-6, h = 1.8e-6, w = 0.1, we = 30e-6;
    const double EI = E * we * t * t * t / 12.0, k = 250e9 * we / 0.2e-6;
    const double ld = detached_length_closed_form(E, t, h, w);
    const double ref = detached_length_on_layer(EI, h, w * we, k);
    std::printf("closed form l_d = %.6g um; on the nitride layer (zero range) %.6g um (%.3e)\n", ld * 1e6, ref * 1e6,
                ref / ld - 1.0);
    // The front settles between quadrature points (8 per element), and the attraction's zone in front
    // of it, about r / |u'| long with u' = 2 b d_0 = 1e-3 the beam's slope where it meets the face
    // (2 um at r = 2 nm), must span a few of them; then the FE front lies within 1e-4 of the layer's
    // solution, and the range adds what it adds: 6.5e-4 at 4 nm, below 1e-4 from 2 nm down.
    std::vector<std::vector<double>> error(3);
    const std::vector<int> meshes{100, 200, 400};
    const std::vector<double> ranges{4e-9, 2e-9, 1e-9};
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        for (double r : ranges) {
            const Case c = read_case_text(lying_case(meshes[i], r), "lying.toml");
            const double s = settled_detached_length(c, 0.85 * ld);
            error[i].push_back(s / ref - 1.0);
            std::printf("m = %d, range %.3g nm: detached %.6g um, %+.2e off the layer's solution, %+.3e off the "
                        "closed form\n",
                        meshes[i], r * 1e9, s * 1e6, s / ref - 1.0, s / ld - 1.0);
        }
    }
    EXPECT_LT(std::abs(error[2][1]), 1e-4);  // m = 400, 2 nm
    EXPECT_LT(std::abs(error[2][2]), 1e-4);  // m = 400, 1 nm
    EXPECT_LT(std::abs(error[1][1]), 1e-4);  // m = 200, 2 nm
    EXPECT_GT(std::abs(error[2][0]), 4.0 * std::abs(error[2][1]));  // the range's own part at 4 nm
    // Resolved, there is one equilibrium, whichever side the front comes from.
    const Case c = read_case_text(lying_case(200, 2e-9), "lying.toml");
    EXPECT_NEAR(settled_detached_length(c, 1.15 * ld) / ref - 1.0, error[1][1], 1e-6);
}

// The semi-analytic solution tends to the closed form as the layer stiffens: s = l_d - 1 / b + ...
TEST(DielectricAdhesion, TheLayerSolutionTendsToTheClosedForm) {
    const double E = 207e9, t = 2e-6, h = 1.8e-6, w = 0.1, we = 30e-6;
    const double EI = E * we * t * t * t / 12.0;
    const double ld = detached_length_closed_form(E, t, h, w);
    double previous = 1.0;
    for (double Ed : {250e9, 4e12, 6.4e13, 1e15, 1.6e16, 2.56e17}) {
        const double k = Ed * we / 0.2e-6;
        const double b = std::pow(k / (4.0 * EI), 0.25);
        const double s = detached_length_on_layer(EI, h, w * we, k);
        const double error = std::abs(s / ld - 1.0);
        std::printf("E_d %.3g Pa: s / l_d - 1 = %.4e, -1 / (b l_d) = %.4e\n", Ed, s / ld - 1.0, -1.0 / (b * ld));
        EXPECT_NEAR(s / ld - 1.0, -1.0 / (b * ld), 2.0 / (b * ld * b * ld) + 1e-12);
        EXPECT_LT(error, previous);
        previous = error;
    }
}

// The peel balance of the stiction check against the clamped-guided span's closed forms: a cantilever
// held on a layer under x in [a, l] peels from a until its free span is l_d long (G = 18 E I h^2 / s^4
// = w w_e), pulls off its layer with the span's shear 12 E I h / l_d^3 and sticks for w above
// 1.5 E t^3 h^2 / l^4 (l_d = l); a clamped-clamped beam held at mid-span peels from both sides.
TEST(DielectricAdhesion, ThePeelBalanceIsTheClampedGuidedSpans) {
    const double E = 200e9, t = 2e-6, we = 30e-6, l = 100e-6, h = 1.5e-6, w = 0.2;
    const double EI = E * we * t * t * t / 12.0;
    const auto layer = [&](const char* ends, double from, double work) {
        char buf[1024];
        std::snprintf(buf, sizeof buf,
                      "[beam]\nlength = \"100 um\"\nwidth = \"30 um\"\nthickness = \"2 um\"\nelements = 20\n%s"
                      "[material]\nyoungs_modulus = \"200 GPa\"\ndensity = \"8900 kg/m^3\"\npoisson_ratio = 0.3\n"
                      "[[electrodes]]\nfrom = %.17g\nto = 1.0\ngap = \"1.7 um\"\ndielectric_thickness = \"0.2 um\"\n"
                      "work_of_adhesion = %.17g\nvoltage = \"0 V\"\n",
                      ends, from, work);
        return read_case_text(buf, "layer.toml");
    };
    const double ld = detached_length_closed_form(E, t, h, w);
    const LayerHold c = layer_hold(layer("", 0.2, w), 0);
    ASSERT_TRUE(c.sticks);
    EXPECT_NEAR(c.air_gap, h, 1e-18);
    EXPECT_NEAR(c.adhesion_energy, w * we, 1e-18);
    EXPECT_NEAR(c.release_from, 18.0 * EI * h * h / std::pow(0.2 * l, 4), 1e-9 * c.release_from);
    EXPECT_EQ(c.release_to, 0.0);  // a free overhang stays flat
    EXPECT_NEAR(c.contact_from, ld, 1e-9 * ld);
    EXPECT_NEAR(c.contact_to, l, 1e-15);
    EXPECT_NEAR(c.restoring_force, 12.0 * EI * h / (ld * ld * ld), 1e-8 * c.restoring_force);
    EXPECT_NEAR(c.critical_work_of_adhesion, 1.5 * E * t * t * t * h * h / std::pow(l, 4), 1e-9 * c.critical_work_of_adhesion);
    EXPECT_NEAR(c.holding_moment, std::sqrt(2.0 * EI * w * we), 1e-12 * c.holding_moment);

    // Clamped at both ends, the layer under all of it: it peels from both clamps, and sticks while the
    // two free spans of l_d leave some contact between them (w above 18 E I h^2 / ((l/2)^4 w_e)).
    const double w_c = 18.0 * EI * h * h / std::pow(0.5 * l, 4) / we;
    EXPECT_FALSE(layer_hold(layer("right = \"clamped\"\n", 0.0, 0.9 * w_c), 0).sticks);
    const double strong = 2.0 * w_c, ld_strong = detached_length_closed_form(E, t, h, strong);
    const LayerHold b = layer_hold(layer("right = \"clamped\"\n", 0.0, strong), 0);
    ASSERT_TRUE(b.sticks);
    EXPECT_EQ(b.release_from, std::numeric_limits<double>::infinity());  // the layer starts at a clamp
    EXPECT_NEAR(b.contact_from, ld_strong, 1e-9 * ld_strong);
    EXPECT_NEAR(b.contact_to, l - ld_strong, 1e-9 * ld_strong);
    EXPECT_NEAR(b.restoring_force, 2.0 * 12.0 * EI * h / std::pow(ld_strong, 3), 1e-8 * b.restoring_force);
    EXPECT_NEAR(b.critical_work_of_adhesion, w_c, 1e-9 * w_c);
}

// The case keys: a layer's work of adhesion and range, the refusals (one line naming file:line:key).
TEST(DielectricAdhesion, CaseKeysAndRefusals) {
    const std::string base = R"(name = "t"
[beam]
length = "100 um"
width = "30 um"
thickness = "2 um"
elements = 10
[material]
youngs_modulus = "200 GPa"
density = "8900 kg/m^3"
poisson_ratio = 0.3
[[electrodes]]
from = 0.2
to = 1.0
gap = "2 um"
voltage = "5 V"
)";  // the electrode's keys from line 16 on
    const Case c = read_case_text(base + "dielectric_thickness = \"0.2 um\"\nwork_of_adhesion = \"50 mJ/m^2\"\n"
                                         "adhesion_range = \"1 nm\"\n",
                                  "ok.toml");
    ASSERT_TRUE(c.electrodes[0].work_of_adhesion);
    EXPECT_DOUBLE_EQ(*c.electrodes[0].work_of_adhesion, 0.05);
    EXPECT_DOUBLE_EQ(c.electrodes[0].adhesion_range, 1e-9);
    const Case d = read_case_text(base + "dielectric_thickness = \"0.2 um\"\nwork_of_adhesion = 0.1\n", "ok.toml");
    EXPECT_DOUBLE_EQ(d.electrodes[0].adhesion_range, kDefaultAdhesionRange);
    EXPECT_FALSE(read_case_text(base, "ok.toml").electrodes[0].work_of_adhesion);
    const auto refused = [&](const std::string& keys, const std::string& prefix) {
        try {
            (void)read_case_text(base + keys, "bad.toml");
            ADD_FAILURE() << "accepted:\n" << keys;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.substr(0, prefix.size()), prefix) << "full message: " << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    };
    refused("work_of_adhesion = 0.1\n", "bad.toml:16: electrodes[0].work_of_adhesion: needs dielectric_thickness");
    refused("dielectric_thickness = \"0.2 um\"\nadhesion_range = \"1 nm\"\n",
            "bad.toml:17: electrodes[0].adhesion_range: needs work_of_adhesion");
    refused("dielectric_thickness = \"0.2 um\"\nwork_of_adhesion = 0\n",
            "bad.toml:17: electrodes[0].work_of_adhesion: must be positive");
    refused("dielectric_thickness = \"0.2 um\"\nwork_of_adhesion = -0.1\n",
            "bad.toml:17: electrodes[0].work_of_adhesion: must be positive");
    refused("dielectric_thickness = \"0.2 um\"\nwork_of_adhesion = 0.1\nadhesion_range = \"-1 nm\"\n",
            "bad.toml:18: electrodes[0].adhesion_range: must be positive");
    refused("dielectric_thickness = \"0.2 um\"\nwork_of_adhesion = \"0.1 N\"\n", "bad.toml:17: electrodes[0].work_of_adhesion:");
    refused("dielectric_thickness = \"0.2 um\"\nwork_of_adhesion = 0.1\n[solver]\nmethod = \"exact\"\n",
            "bad.toml:19: solver.method: \"exact\" cannot take the adhesive dielectric contact of electrodes[0]");
}

// A capacitive cantilever (10 elements, Rayleigh damping) lands on its adhesive nitride under a 60 V
// pulse; when the voltage falls it stays stuck (w = 0.1 J/m^2) or lets go (0.01 J/m^2). kinetic +
// strain + layer (the adhesion's potential included) + electrical + dissipated - source work stays
// constant at every sample, to 1e-6 of the source's work.
TEST(DielectricAdhesion, TheEnergyLedgerIsConstantThroughLandingStickingAndRelease) {
    const auto run = [](double w, double horizon_us, double rtol) {
        char buf[2048];
        std::snprintf(buf, sizeof buf, R"(
[beam]
length = "117 um"
width = "30 um"
thickness = "2 um"
elements = 10
[material]
youngs_modulus = "207 GPa"
density = "8902 kg/m^3"
poisson_ratio = 0.31
[damping]
ratios = [0.005, 0.005]
modes = [1, 2]
[[electrodes]]
from = 0.1
to = 1.0
gap = "2 um"
dielectric_thickness = "0.2 um"
dielectric_permittivity = 7.5
work_of_adhesion = "%.17g J/m^2"
voltage = "60 V"
waveform = "pulse"
t_on = "0 us"
rise = "0.5 us"
hold = "3 us"
fall = "0.5 us"
[initial]
kind = "rest"
[solver]
method = "cvode"
horizon = "%.17g us"
output_step = "20 ns"
rtol = %.17g
)",
                      w, horizon_us, rtol);
        const Case c = read_case_text(buf, "landing.toml");
        const BuiltProblem b = build_transient_problem(c);
        CvodeOptions o;
        o.rtol = rtol;
        return solve_cvode(b.problem, o);
    };
    const auto total = [](const EnergyLedger& e) {
        return e.kinetic + e.strain + e.contact_spring + e.electrical + e.rayleigh_dissipated + e.contact_dissipated -
               e.external_work;
    };
    for (const double w : {0.1, 0.01}) {
        const TransientResult r = w > 0.05 ? run(w, 8.0, 1e-9) : run(w, 20.0, 1e-9);
        ASSERT_FALSE(r.episodes.empty());
        const double scale = r.final_energy.external_work;
        ASSERT_GT(scale, 0.0);
        double worst = 0.0, deepest = 0.0;
        for (const EnergyLedger& e : r.history.energy) {
            worst = std::max(worst, std::abs(total(e) - total(r.initial_energy)) / scale);
            deepest = std::min(deepest, e.contact_spring);
        }
        EXPECT_LT(worst, 1e-6) << w;
        EXPECT_LT(deepest, 0.0) << w;  // the adhesion's potential well was entered
        const bool stuck = r.episodes.back().closed_at_end;
        EXPECT_EQ(stuck, w > 0.05) << w;
        std::printf("w = %.3g J/m^2: %zu episodes, %s at %.3g us, ledger constant to %.2e of the source's work\n", w,
                    r.episodes.size(), stuck ? "stuck" : "released", r.t_end * 1e6, worst);
    }
}

}  // namespace
}  // namespace vi
