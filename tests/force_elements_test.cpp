// The force-element contract (forces/force_element.hpp), checked for every element in every mode:
// the tangent is the derivative of the force (central differences), the stored energy's gradient is
// minus the conservative part of the force (except for a prescribed load), the dissipated power is
// what the velocity-dependent part takes out, the energy balance dE/dt = -f.v - dissipated + input
// holds along any motion, and the piecewise-linear form the exact solver reads gives the same force.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "forces/adhesive_contact.hpp"
#include "forces/dielectric_contact.hpp"
#include "forces/force_set.hpp"
#include "forces/hertz_contact.hpp"
#include "fem/beam_element.hpp"
#include "forces/electrostatic_pad.hpp"
#include "forces/kelvin_voigt_contact.hpp"
#include "forces/midplane_stretching.hpp"
#include "forces/point_load_element.hpp"
#include "forces/squeeze_film.hpp"
#include "problem/element_families.hpp"
#include "support/contract_elements.hpp"
#include "support/pad_points.hpp"
#include "support/test_elements.hpp"

namespace vi {
namespace {

struct Sample {
    double t;
    std::vector<double> q, v;
};

std::vector<double> force_at(const ForceElement& e, const Sample& s, int mode) {
    std::vector<double> f(e.dofs().size(), 0.0);
    e.add_force(ElementState{s.t, s.q.data(), s.v.data(), nullptr}, mode, f.data());
    return f;
}

// States around the element's working range: displacements of +-1 um, velocities of +-0.5 m/s.
std::vector<Sample> samples(std::size_t dofs) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Sample> out;
    for (int k = 0; k < 20; ++k) {
        Sample s{1e-6 * (1.0 + u(rng)), {}, {}};
        for (std::size_t i = 0; i < dofs; ++i) {
            s.q.push_back(1e-6 * u(rng));
            s.v.push_back(0.5 * u(rng));
        }
        out.push_back(s);
    }
    return out;
}

// A dielectric layer on an element of length 1 m: gap 0.3 um, layer 0.2 um, line stiffness 1e3 N/m^2.
ForceElementPtr dielectric_layer(double sign, std::optional<AdhesiveLayerLaw> law) {
    PadGeometry g;
    g.sign = sign;
    g.gap = 0.3e-6;
    g.dielectric_thickness = 0.2e-6;
    g.width = 30e-6;
    g.to = 1.0;
    const std::string name = sign < 0.0 ? "electrodes[0].dielectric" : "electrodes[1].dielectric";
    if (law) return std::make_shared<DielectricContact>(name, std::vector<int>{0, 1, 2, 3}, test::one_element_points(1.0), g, *law);
    return std::make_shared<DielectricContact>(name, std::vector<int>{0, 1, 2, 3}, test::one_element_points(1.0), g, 1e3);
}

// An electrode over one element 1 m long (as the films below), 3 um from the axis with a 0.2 um
// dielectric, at 40 V times a ramp (so the source works: the input power is not 0).
ForceElementPtr electrode(double sign, Fringing fringing) {
    PadGeometry g;
    g.sign = sign;
    g.gap = 3e-6;
    g.dielectric_thickness = 0.2e-6;
    g.dielectric_permittivity = 7.5;
    g.width = 30e-6;
    g.beam_thickness = 2e-6;
    g.fringing = fringing;
    g.to = 1.0;
    TimeFunction ramp;
    ramp.kind = TimeFunction::Kind::table;
    ramp.times = {0.0, 1e-5};
    ramp.values = {0.2, 1.0};
    return std::make_shared<ElectrostaticPad>(sign > 0.0 ? "electrodes[0]" : "electrodes[1]",
                                              std::vector<int>{0, 1, 2, 3}, test::one_element_points(1.0), g, 40.0, ramp);
}

// Mid-plane stretching of one element 1 m long, its v and theta at both ends free, E A / l = 1e6 N/m.
ForceElementPtr stretching() {
    const ElementMatrix g = element_geometric_stiffness(1.0);
    const int bending[] = {1, 2, 4, 5};
    Eigen::SparseMatrix<double> G(4, 4);
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) t.emplace_back(i, j, g(bending[i], bending[j]));
    }
    G.setFromTriplets(t.begin(), t.end());
    return std::make_shared<MidplaneStretching>("beam.stretching", G, 1e6);
}

using Named = test::ContractElement;

// The samples of the elements this file holds; an element's own test file adds its samples
// (support/contract_elements.hpp).
std::vector<Named> own_elements() {
    return {
        {"contact below, damped", "support contacts",
         [] { return std::make_shared<KelvinVoigtContact>("supports[0]", 0, 1.0, 0.2e-6, 1000.0, 5e-5, 1e-4); }},
        {"contact above, undamped", "support contacts",
         [] { return std::make_shared<KelvinVoigtContact>("supports[1]", 0, -1.0, -0.3e-6, 50.0, 0.0, 1e-4); }},
        // Pull-off 1 uN, range 0.3 um: the samples' +-1 um reach every piece of the cohesive law.
        {"adhesive contact below, damped", "support contacts",
         [] {
             return std::make_shared<AdhesiveContact>("supports[2]", 0, 1.0, 0.2e-6, 1000.0, 5e-5, 1e-4, 1e-6, 0.3e-6,
                                                      "DMT");
         },
         false},
        {"adhesive contact above, undamped", "support contacts",
         [] {
             return std::make_shared<AdhesiveContact>("supports[3]", 0, -1.0, -0.3e-6, 50.0, 0.0, 1e-4, 5e-6, 0.2e-6,
                                                      "JKR");
         },
         false},
        {"step load on four DOFs", "point loads",
         [] {
             TimeFunction g;
             g.kind = TimeFunction::Kind::step;
             g.t_on = 1e-6;
             return std::make_shared<PointLoadElement>("loads[0]", std::vector<int>{0, 1, 2, 3},
                                                       std::vector<double>{0.5, 1e-7, 0.5, -1e-7}, 2e-6, g, 5e-5);
         },
         true,
         false},
        {"harmonic load", "point loads",
         [] {
             TimeFunction g;
             g.kind = TimeFunction::Kind::harmonic;
             g.frequency_hz = 1e5;
             g.phase = 0.3;
             g.offset = 0.2;
             return std::make_shared<PointLoadElement>("loads[1]", std::vector<int>{0}, std::vector<double>{1.0}, 1e-6,
                                                       g, 1e-4);
         },
         true,
         false},
        // One element 1 m long: its rotations then move the film's points by as much as its
        // displacements do, so that the central differences (steps of 1e-12) resolve both.
        {"squeeze film below, slip flow", "squeeze films",
         [] {
             const double L = 1.0;
             return std::make_shared<SqueezeFilm>("films[0]", std::vector<int>{0, 1, 2, 3}, test::one_element_points(L),
                                                  FilmGeometry{-1.0, 3e-6, 30e-6, 0.0, L}, FilmGas{1.85e-5, 68e-9});
         }},
        {"squeeze film above, rarefied", "squeeze films",
         [] {
             const double L = 1.0;
             return std::make_shared<SqueezeFilm>("films[1]", std::vector<int>{0, 1, 2, 3}, test::one_element_points(L),
                                                  FilmGeometry{1.0, 2.5e-6, 20e-6, 0.0, L}, FilmGas{1.85e-5, 7e-6});
         }},
        {"squeeze film below a perforated plate", "squeeze films",
         [] {
             const double L = 1.0;
             std::vector<PadPoint> points = test::one_element_points(L);
             // Round 8 um holes at 18 um through 2 um of plate, the strip 100 um wide.
             std::vector<FilmPerforation> holes(points.size(), FilmPerforation{8e-6, 18e-6, true, 2e-6, 100e-6});
             return std::make_shared<SqueezeFilm>("films[2]", std::vector<int>{0, 1, 2, 3}, std::move(points),
                                                  FilmGeometry{-1.0, 3e-6, 100e-6, 0.0, L}, FilmGas{1.85e-5, 68e-9},
                                                  std::move(holes));
         }},
        // The layers on one element 1 m long (as the films), their face 0.1 um from the axis, so that
        // the samples' +-1 um press in, pass through the attraction's range and leave it.
        {"dielectric contact below", "dielectric layers",
         [] { return dielectric_layer(-1.0, std::nullopt); },
         false},
        // W = 0.1 k r^2: the rest penetration lies where the layer's stiffness comes in (d_0 < r).
        {"adhesive dielectric contact below, soft pull", "dielectric layers",
         [] { return dielectric_layer(-1.0, AdhesiveLayerLaw(1e3, 0.1 * 1e3 * 0.3e-6 * 0.3e-6, 0.3e-6)); },
         false},
        // W = 5 k r^2: it lies beyond (d_0 > r), where the layer is a linear spring.
        {"adhesive dielectric contact above, strong pull", "dielectric layers",
         [] { return dielectric_layer(1.0, AdhesiveLayerLaw(1e3, 5.0 * 1e3 * 0.2e-6 * 0.2e-6, 0.2e-6)); },
         false},
        {"electrode above, parallel plate", "electrostatic pads", [] { return electrode(1.0, Fringing::none); }, false},
        {"electrode below, Meijs-Fokkema fringing", "electrostatic pads", [] { return electrode(-1.0, Fringing::meijs_fokkema); }, false},
        {"mid-plane stretching", "mid-plane stretching", [] { return stretching(); }, false},
        // k of gold on gold through R = 2 um (9.05e7 N/m^(3/2)); alpha 0.5 s/m keeps 1 + alpha dd/dt
        // in (0.75, 1.25) over the samples' +-0.5 m/s.
        {"Hertz contact below, Hunt-Crossley damped", "Hertz contacts",
         [] { return std::make_shared<HertzContact>("supports[4]", 0, 1.0, 0.2e-6, 1e-4, 9.05e7, 0.5, 2e-6); },
         false},
        {"Hertz contact above, undamped", "Hertz contacts",
         [] { return std::make_shared<HertzContact>("supports[5]", 0, -1.0, -0.3e-6, 1e-4, 9.05e7, 0.0, 2e-6); },
         false},
    };
}

const bool kOwnElementsAdded = [] {
    for (Named& n : own_elements()) test::add_contract_element(std::move(n));
    return true;
}();

// Every sample, this file's and those the elements' own test files add.
const std::vector<Named>& elements() { return test::contract_elements(); }

// Every family of the registry has its elements in the contract: a new family's test file adds
// samples of its element (add_contract_element), or this fails naming the family.
TEST(ForceElementContractCoverage, EveryRegisteredFamilyHasSamples) {
    ASSERT_TRUE(kOwnElementsAdded);
    for (const ElementFamily* family : element_families()) {
        const bool sampled = std::any_of(elements().begin(), elements().end(),
                                         [&](const Named& n) { return n.family == family->name(); });
        EXPECT_TRUE(sampled) << "the family \"" << family->name()
                             << "\" has no sample in the force-element contract (test::add_contract_element)";
    }
}

class ForceElementContract : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ForceElementContract, TangentIsTheDerivativeOfTheForce) {
    const Named n = elements()[GetParam()];
    const ForceElementPtr e = n.make();
    const std::size_t m = e->dofs().size();
    double worst = 0.0;
    for (int mode = 0; mode < e->modes(); ++mode) {
        for (const Sample& s : samples(m)) {
            std::vector<double> dq(m * m, 0.0), dv(m * m, 0.0);
            e->add_tangent(ElementState{s.t, s.q.data(), s.v.data(), nullptr}, mode, dq.data(), dv.data());
            for (std::size_t j = 0; j < m; ++j) {
                for (int which = 0; which < 2; ++which) {
                    // 1e-5 of the states' size: truncation (h/g)^2 and roundoff (eps g/h, amplified where a
                    // distributed element's point contributions cancel) both stay below 1e-8.
                    const double h = which == 0 ? 1e-11 : 1e-5;
                    Sample plus = s, minus = s;
                    (which == 0 ? plus.q : plus.v)[j] += h;
                    (which == 0 ? minus.q : minus.v)[j] -= h;
                    const std::vector<double> fp = force_at(*e, plus, mode), fm = force_at(*e, minus, mode);
                    for (std::size_t i = 0; i < m; ++i) {
                        const double fd = (fp[i] - fm[i]) / (2.0 * h);
                        const double an = (which == 0 ? dq : dv)[i * m + j];
                        const double scale = std::max({std::abs(fd), std::abs(an), 1e-30});
                        worst = std::max(worst, std::abs(fd - an) / scale);
                    }
                }
            }
        }
    }
    EXPECT_LT(worst, 1e-7) << n.label;
}

double stored(const ForceElement& e, double t, const std::vector<double>& q, const std::vector<double>& v, int mode) {
    return e.stored_energy(ElementState{t, q.data(), v.data(), nullptr}, mode);
}

// Also: add_force_and_power (the solvers' fused call) gives add_force and dissipated_power.
TEST_P(ForceElementContract, EnergyAndPowersMatchTheForce) {
    const Named n = elements()[GetParam()];
    const ForceElementPtr e = n.make();
    const std::size_t m = e->dofs().size();
    for (int mode = 0; mode < e->modes(); ++mode) {
        for (const Sample& s : samples(m)) {
            const ElementState st{s.t, s.q.data(), s.v.data(), nullptr};
            Sample still = s;
            std::fill(still.v.begin(), still.v.end(), 0.0);
            const std::vector<double> f = force_at(*e, s, mode), f0 = force_at(*e, still, mode);
            double power = 0.0, damper_power = 0.0, scale = 1e-30;
            for (std::size_t i = 0; i < m; ++i) {
                power += f[i] * s.v[i];
                damper_power -= (f[i] - f0[i]) * s.v[i];
                scale += std::abs(f[i] * s.v[i]);
                // -dE/dq_i by central differences equals the conservative (v = 0) force.
                if (n.potential) {
                    const double h = 1e-12;
                    Sample plus = still, minus = still;
                    plus.q[i] += h;
                    minus.q[i] -= h;
                    const double dE = (stored(*e, s.t, plus.q, plus.v, mode) - stored(*e, s.t, minus.q, minus.v, mode)) / (2.0 * h);
                    EXPECT_NEAR(-dE, f0[i], 1e-6 * std::abs(f0[i]) + 1e-18) << n.label << " mode " << mode;
                }
            }
            // The fused call a solver's right-hand side makes gives the same force and power.
            std::vector<double> fused(m, 0.0);
            const double fused_power = e->add_force_and_power(st, mode, fused.data());
            EXPECT_NEAR(fused_power, e->dissipated_power(st, mode), 1e-13 * scale) << n.label << " mode " << mode;
            for (std::size_t i = 0; i < m; ++i)
                EXPECT_NEAR(fused[i], f[i], 1e-13 * std::abs(f[i]) + 1e-300) << n.label << " mode " << mode;
            const double dissipated = e->dissipated_power(st, mode), input = e->input_power(st, mode);
            EXPECT_NEAR(dissipated, damper_power, 1e-12 * scale) << n.label;
            EXPECT_GE(dissipated, 0.0) << n.label;
            // Along the motion (q + v dt, t + dt) the stored energy changes by what the beam does on the
            // element, less what it dissipates, plus what a source puts in (an electrode's -C V dV/dt, a
            // load's Q(t) v).
            const double dt = 1e-13;
            Sample ahead = s, behind = s;
            for (std::size_t i = 0; i < m; ++i) {
                ahead.q[i] += s.v[i] * dt;
                behind.q[i] -= s.v[i] * dt;
            }
            const double rate = (stored(*e, s.t + dt, ahead.q, s.v, mode) - stored(*e, s.t - dt, behind.q, s.v, mode)) / (2.0 * dt);
            EXPECT_NEAR(rate, -power - dissipated + input, 1e-6 * (scale + std::abs(input))) << n.label << " mode " << mode;
        }
    }
}

// The exact solver integrates the element through its linear form: the same force in every mode
// (a unilateral spring-damper acts in its closed mode only). A squeeze film is not piecewise linear
// and must say so (the exact solver then refuses it by name).
TEST_P(ForceElementContract, LinearFormGivesTheSameForce) {
    const Named n = elements()[GetParam()];
    const ForceElementPtr e = n.make();
    const std::optional<LinearForm> lf = e->linear_form();
    if (!n.linear || e->kind() == "squeeze film") {
        EXPECT_FALSE(lf.has_value()) << n.label;
        return;
    }
    ASSERT_TRUE(lf.has_value()) << n.label;
    for (int mode = 0; mode < e->modes(); ++mode) {
        for (const Sample& s : samples(e->dofs().size())) {
            const std::vector<double> f = force_at(*e, s, mode);
            std::vector<double> g(f.size(), 0.0);
            std::visit(
                [&](const auto& term) {
                    using T = std::decay_t<decltype(term)>;
                    if constexpr (std::is_same_v<T, UnilateralSpringDamper>) {
                        ASSERT_EQ(e->dofs().front(), term.dof);
                        if (mode == e->contact_mode()) {
                            g[0] = term.stiffness * (term.surface - s.q[0]) - term.damping * s.v[0];
                        }
                    } else {
                        for (std::size_t i = 0; i < term.dofs.size(); ++i) {
                            ASSERT_EQ(e->dofs()[i], term.dofs[i]);
                            g[i] = term.amplitude * term.time(s.t) * term.weights[i];
                        }
                    }
                },
                lf->term);
            for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(f[i], g[i], 1e-14 * std::abs(g[i]) + 1e-30) << n.label;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllElements, ForceElementContract, ::testing::Range<std::size_t>(0, elements().size()));

// The contact's switching rules: open, it closes exactly where d > 0 and F > 0 both hold (its
// switching function crosses zero upward there); closed, it opens where F falls through 0.
TEST(KelvinVoigtContact, SwitchingFunctionsStateTheNoTensionRule) {
    const KelvinVoigtContact c("supports[0]", 0, 1.0, 0.0, 1000.0, 5e-5, 1e-4);
    for (const Sample& s : samples(1)) {
        const ElementState st{s.t, s.q.data(), s.v.data(), nullptr};
        const double d = c.penetration(st), F = c.force_magnitude(st);
        EXPECT_EQ(c.switching_function(st, 0) > 0.0, d > 0.0 && F > 0.0);
        EXPECT_EQ(c.switching_function(st, 1) > 0.0, F < 0.0);
        EXPECT_EQ(c.mode_after_switch(0), 1);
        EXPECT_EQ(c.mode_after_switch(1), 0);
    }
    // Touching (d = 0) and moving in: closed from the start, as the exact solver's search closes it.
    const double q = 0.0, v_in = -0.1, v_out = 0.1;
    EXPECT_EQ(c.initial_mode(ElementState{0.0, &q, &v_in, nullptr}), 1);
    EXPECT_EQ(c.initial_mode(ElementState{0.0, &q, &v_out, nullptr}), 0);
}

// The adhesive contact's rules: closed, it holds until F falls below -F_po; open, it closes where
// d > d_po and F > -F_po both hold; the attraction is F_po at d_po, half of it mid-zone, 0 beyond.
TEST(AdhesiveContact, SwitchingFunctionsStateThePullOffRule) {
    const double kc = 1000.0, fpo = 1e-6, range = 2e-9;
    const AdhesiveContact c("supports[0]", 0, 1.0, 0.0, kc, 5e-5, 1e-4, fpo, range, "DMT");
    const double d_po = -fpo / kc;
    for (const Sample& s : samples(1)) {
        const ElementState st{s.t, s.q.data(), s.v.data(), nullptr};
        const double d = c.penetration(st), F = c.contact_reading(st).force;
        EXPECT_EQ(c.switching_function(st, 1) > 0.0, F < -fpo);
        EXPECT_EQ(c.switching_function(st, 0) > 0.0, d > d_po && F > -fpo);
    }
    EXPECT_DOUBLE_EQ(c.attraction(d_po), fpo);
    EXPECT_DOUBLE_EQ(c.attraction(d_po + 1e-9), fpo);
    EXPECT_NEAR(c.attraction(d_po - 0.5 * range), 0.5 * fpo, 1e-12 * fpo);
    EXPECT_EQ(c.attraction(d_po - range), 0.0);
    EXPECT_EQ(c.attraction(d_po - 2.0 * range), 0.0);
    // At d_po both modes store the same energy: a switch there is no jump in the ledger.
    const double q = -d_po, v = 0.0;
    const ElementState at{0.0, &q, &v, nullptr};
    EXPECT_NEAR(c.stored_energy(at, 0), c.stored_energy(at, 1), 1e-12 * std::abs(c.stored_energy(at, 1)));
}

TEST(ForceSet, TheFirstElementThatIsNotPiecewiseLinearIsNamed) {
    // An element with no linear form rules the exact solver out; the set names it.
    ForceSet set{own_elements()[0].make(), std::make_shared<test::CubicSpring>(0, 1.0), own_elements()[4].make()};
    ASSERT_EQ(own_elements()[4].label, "step load on four DOFs");
    ASSERT_NE(first_nonlinear(set), nullptr);
    EXPECT_EQ(first_nonlinear(set)->name(), "springs[0]");
    set.erase(set.begin() + 1);
    EXPECT_EQ(first_nonlinear(set), nullptr);
    EXPECT_EQ(contact_indices(set), std::vector<int>{0});
}

}  // namespace
}  // namespace vi
