// The estimates and reported values that depend on the beam's section, over a beam of sections
// (docs/model.md §2.1): a beam written as one section unlike the plain [beam] defaults answers as
// the plain beam of that section, a uniform beam as sections as the plain beam, and a stepped beam
// takes the section named for each: run-size estimates, dimensionless mode amplitudes, a film's
// squeeze number, the peel of a beam on an adhesive layer and a stuck cantilever's detached length,
// the fringing formula's range check and the summary's sections.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
#include <string>

#include "case_text_fixture.hpp"
#include "fem/system.hpp"
#include "io/case_reader.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/modal_analysis.hpp"
#include "model/input_error.hpp"
#include "model/run_estimate.hpp"
#include "model/section_scales.hpp"
#include "problem/beam_model.hpp"
#include "forces/hertz_contact.hpp"
#include "impacts/simulation.hpp"
#include "problem/film_elements.hpp"
#include "report/transient_output.hpp"
#include "statics/layer_hold.hpp"
#include "study/stiction/stiction.hpp"
#include "support/input_error_of.hpp"

namespace vi {
namespace sections_estimates_test {
namespace {

// The base case (l = 100 um, w = 30 um, t = 2 um, E = 200 GPa, rho = 8900) with `extra` appended.
Case with(const std::string& extra) { return read_case_text(test::kBaseCase + extra, "estimates.toml"); }

// One section 60 um wide and 3 um thick over the whole beam, and the plain beam of that section.
const std::string kOneWide = "[[beam.sections]]\nfrom = 0\nto = 1\nwidth = \"60 um\"\nthickness = \"3 um\"\n";
Case plain_wide(const std::string& extra) {
    std::string text = test::kBaseCase;
    text.replace(text.find("width = \"30 um\""), 15, "width = \"60 um\"");
    text.replace(text.find("thickness = \"2 um\""), 18, "thickness = \"3 um\"");
    return read_case_text(text + extra, "estimates.toml");
}
// Two equal halves that repeat the plain beam.
const std::string kHalves = "[[beam.sections]]\nfrom = 0\nto = 0.5\n[[beam.sections]]\nfrom = 0.5\nto = 1\n";
// A wide thick root and a narrow thin tip.
const std::string kStepped = "[[beam.sections]]\nfrom = 0\nto = 0.4\nwidth = \"30 um\"\nthickness = \"4 um\"\n"
                             "[[beam.sections]]\nfrom = 0.4\nto = 1\nwidth = \"15 um\"\nthickness = \"1.2 um\"\n";

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(SectionsEstimates, RunEstimateTakesTheSections) {
    const RunEstimate plain = estimate_run(with("")), halves = estimate_run(with(kHalves));
    EXPECT_LT(rel(halves.omega1, plain.omega1), 1e-14);
    EXPECT_LT(rel(halves.omega_top, plain.omega_top), 1e-14);
    EXPECT_LT(rel(halves.bending_stiffness, plain.bending_stiffness), 1e-14);
    const RunEstimate one = estimate_run(with(kOneWide)), wide = estimate_run(plain_wide(""));
    EXPECT_LT(rel(one.omega1, wide.omega1), 1e-14);
    EXPECT_LT(rel(one.omega_top, wide.omega_top), 1e-14);
    EXPECT_LT(rel(one.bending_stiffness, wide.bending_stiffness), 1e-14);
    // Stepped: the mesh's top frequency stays under the bound of its stiffest part (the plain
    // [beam]'s 2 um would put it below), mode 1 within 5 % of the model's (Rayleigh's method in the
    // static deflection).
    const Case c = with(kStepped);
    const RunEstimate stepped = estimate_run(c);
    const System s = build_system(c, SupportModel::none);
    const ModeSet all = all_modes_dense(submatrix(s.K, s.bending), submatrix(s.M, s.bending));
    const double top = all.omega[all.omega.size() - 1];
    std::printf("stepped: omega_top bound %.4g, FE top %.4g, plain-beam bound %.4g; omega1 estimate %.4g, FE %.4g\n",
                stepped.omega_top, top, estimate_run(with("")).omega_top, stepped.omega1, all.omega[0]);
    EXPECT_GE(stepped.omega_top, top);
    EXPECT_LT(estimate_run(with("")).omega_top, top);
    EXPECT_LT(rel(stepped.omega1, all.omega[0]), 0.05);
}

// The model layer's section scales are the finite-element model's section properties.
TEST(SectionsEstimates, SectionScalesAreTheModelsSections) {
    const std::string layers =
        "[[materials]]\nname = \"a\"\nyoungs_modulus = \"116 GPa\"\ndensity = \"4506 kg/m^3\"\npoisson_ratio = 0.32\n"
        "[[materials]]\nname = \"b\"\nyoungs_modulus = \"79 GPa\"\ndensity = \"19300 kg/m^3\"\npoisson_ratio = 0.42\n"
        "[[beam.sections]]\nfrom = 0\nto = 0.3\nwidth = \"20 um\"\n"
        "layers = [{ material = \"a\", thickness = \"50 nm\" }, { material = \"b\", thickness = \"1.5 um\" }]\n"
        "[[beam.sections]]\nfrom = 0.3\nto = 1\nthickness = \"1 um\"\n";
    const Case c = with(layers);
    const std::vector<SectionScale> scales = section_scales(c);
    const System s = build_system(c, SupportModel::none);
    ASSERT_EQ(scales.size(), s.sections.size());
    for (std::size_t k = 0; k < scales.size(); ++k) {
        EXPECT_LT(rel(scales[k].EI, s.sections[k].EI), 1e-13) << k;
        EXPECT_LT(rel(scales[k].rho_A, s.sections[k].rho_A), 1e-13) << k;
    }
}

// Y = |v| sqrt(m), m the beam's mass: a uniform beam written as one section unlike [beam] (or as
// halves) has the amplitudes of the plain beam of that section; the stepped beam's amplitude is
// |v| sqrt(rho (w t L) summed).
TEST(SectionsEstimates, ModeAmplitudesUseTheBeamsMass) {
    const ModalStudy one = modal_study(with(kOneWide), 3, SupportModel::pin);
    const ModalStudy wide = modal_study(plain_wide(""), 3, SupportModel::pin);
    const ModalStudy halves = modal_study(with(kHalves), 3, SupportModel::pin);
    const ModalStudy plain = modal_study(with(""), 3, SupportModel::pin);
    for (std::size_t i = 0; i < 3; ++i) {
        const std::vector<ShapePeak>& a = one.unsupported.bending[i].features.peaks;
        const std::vector<ShapePeak>& b = wide.unsupported.bending[i].features.peaks;
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t k = 0; k < a.size(); ++k) EXPECT_LT(rel(a[k].amplitude, b[k].amplitude), 1e-9) << i << " " << k;
        const std::vector<ShapePeak>& h = halves.unsupported.bending[i].features.peaks;
        const std::vector<ShapePeak>& p = plain.unsupported.bending[i].features.peaks;
        ASSERT_EQ(h.size(), p.size());
        for (std::size_t k = 0; k < h.size(); ++k) EXPECT_LT(rel(h[k].amplitude, p[k].amplitude), 1e-9) << i << " " << k;
    }
    const Case c = with(kStepped);
    const ModalStudy stepped = modal_study(c, 1, SupportModel::pin);
    const double mass = 8900.0 * (30e-6 * 4e-6 * 40e-6 + 15e-6 * 1.2e-6 * 60e-6);
    const Mode& m = stepped.unsupported.bending.front();
    const double tip = std::abs(m.shape[global_dof(stepped.unsupported.system.mesh.node_count() - 1, 1)]);
    EXPECT_LT(rel(m.features.peaks.back().amplitude, tip * std::sqrt(mass)), 1e-12);
    EXPECT_LT(rel(beam_mass(stepped.unsupported.system), mass), 1e-14);
}

// sigma = 12 mu_eff w^2 omega / (p g^2) with w the widest section under the film: as the plain beam
// over halves that repeat it, (90 / 30)^2 times it over a 90 um tip, the plain value over the root.
TEST(SectionsEstimates, SqueezeNumberOfTheWidestSectionUnderTheFilm) {
    const std::string film = "[air]\n[[films]]\nfrom = 0.2\nto = 0.9\ngap = \"2 um\"\n";
    const double plain = film_regimes(with(film), 1e6).front().squeeze_number;
    EXPECT_EQ(film_regimes(with(kHalves + film), 1e6).front().squeeze_number, plain);
    const std::string wide_tip = "[[beam.sections]]\nfrom = 0\nto = 0.6\n[[beam.sections]]\nfrom = 0.6\nto = 1\nwidth = \"90 um\"\n";
    EXPECT_NEAR(film_regimes(with(wide_tip + film), 1e6).front().squeeze_number, 9.0 * plain, 1e-13 * plain);
    const std::string root_film = "[air]\n[[films]]\nfrom = 0.1\nto = 0.5\ngap = \"2 um\"\n";
    EXPECT_EQ(film_regimes(with(wide_tip + root_film), 1e6).front().squeeze_number, plain);
}

const std::string kLayer = "[[electrodes]]\nfrom = 0.2\nto = 1.0\ngap = \"1.7 um\"\ndielectric_thickness = \"0.2 um\"\n"
                           "work_of_adhesion = 0.2\nvoltage = \"0 V\"\n";

// The peel on an adhesive layer takes the width and EI under the electrode: one section of 60 um x
// 3 um holds as the plain beam of 60 um x 3 um.
TEST(SectionsEstimates, LayerHoldTakesTheSectionUnderTheElectrode) {
    const LayerHold one = layer_hold(with(kOneWide + kLayer), 0), wide = layer_hold(plain_wide(kLayer), 0);
    EXPECT_LT(rel(one.adhesion_energy, wide.adhesion_energy), 1e-15);
    EXPECT_LT(rel(one.holding_moment, wide.holding_moment), 1e-14);
    EXPECT_LT(rel(one.contact_from, wide.contact_from), 1e-12);
    EXPECT_LT(rel(one.restoring_force, wide.restoring_force), 1e-9);
    EXPECT_LT(rel(one.critical_work_of_adhesion, wide.critical_work_of_adhesion), 1e-9);
    EXPECT_NEAR(wide.adhesion_energy, 0.2 * 60e-6, 1e-18);
}

// A part of the stepped beam inside one section peels as the plain beam of that section, from
// either end (the right end's sections mirrored); the part past the tip keeps the tip's section.
TEST(SectionsEstimates, PeelOfAPartTakesItsSections) {
    const Case stepped = with(kStepped);
    const auto plain = [](const char* w, const char* t) {
        std::string text = test::kBaseCase;
        text.replace(text.find("width = \"30 um\""), 15, std::string("width = \"") + w + "\"");
        text.replace(text.find("thickness = \"2 um\""), 18, std::string("thickness = \"") + t + "\"");
        return read_case_text(text, "plain.toml");
    };
    const PeelRate root = peel_release_rate(stepped, EndCondition::clamped, 30e-6, 1e-6, 4, true);
    const PeelRate root_plain = peel_release_rate(plain("30 um", "4 um"), EndCondition::clamped, 30e-6, 1e-6, 4, true);
    EXPECT_LT(rel(root.release_rate, root_plain.release_rate), 1e-12);
    const PeelRate tip = peel_release_rate(stepped, EndCondition::clamped, 50e-6, 1e-6, 4, false);
    const PeelRate tip_plain = peel_release_rate(plain("15 um", "1.2 um"), EndCondition::clamped, 50e-6, 1e-6, 4, true);
    EXPECT_LT(rel(tip.release_rate, tip_plain.release_rate), 1e-12);
    const std::vector<BeamSection> past = part_sections(stepped.beam, 150e-6, true);
    ASSERT_EQ(past.size(), 2u);
    EXPECT_NEAR(past[0].to, 40.0 / 150.0, 1e-15);
    EXPECT_EQ(past[1].to, 1.0);
    const std::vector<BeamSection> mirrored = part_sections(stepped.beam, 80e-6, false);
    ASSERT_EQ(mirrored.size(), 2u);
    EXPECT_NEAR(mirrored[0].to, 60.0 / 80.0, 1e-15);
    EXPECT_EQ(mirrored[0].thickness, stepped.beam.sections[1].thickness);
}

// The stuck cantilever's detached length: (18 EI h^2 / (w gamma))^(1/4) is the closed form's
// E w t^3 / 12; one wide section answers as the plain wide beam.
TEST(SectionsEstimates, DetachedLengthTakesTheSection) {
    const double E = 200e9, w = 60e-6, t = 3e-6;
    EXPECT_LT(rel(detached_length_of_section(E * w * t * t * t / 12.0, w, 1e-6, 0.1),
                  detached_length_closed_form(E, t, 1e-6, 0.1)), 1e-14);
    const std::string stop = "[[supports]]\nposition = 1.0\ngap = \"1 um\"\nstiffness = \"1000 N/m\"\n"
                             "adhesion = \"dmt\"\nwork_of_adhesion = \"0.1 J/m^2\"\ncontact_radius = \"1 um\"\n";
    const StictionResult one = stiction_check(with(kOneWide + stop)), wide = stiction_check(plain_wide(stop));
    ASSERT_EQ(one.detached.size(), 1u);
    EXPECT_LT(rel(one.detached[0].closed_form, wide.detached[0].closed_form), 1e-14);
    EXPECT_LT(rel(one.detached[0].finite_element, wide.detached[0].finite_element), 1e-9);
}

std::string error_of(const std::string& extra) {
    return test::input_error_of([&] { with(extra); });
}

// Meijs-Fokkema's range (0.3 <= t/g): the plain 2 um beam at a 10 um gap is outside, a 4 um section
// under the electrode inside.
TEST(SectionsEstimates, FringingRangeTakesTheSectionUnderTheElectrode) {
    const std::string electrode = "[[electrodes]]\nfrom = 0.5\nto = 0.9\ngap = \"10 um\"\nfringing = \"meijs-fokkema\"\n"
                                  "voltage = \"1 V\"\n";
    const std::string thick = "[[beam.sections]]\nfrom = 0\nto = 0.4\n[[beam.sections]]\nfrom = 0.4\nto = 1\n"
                              "thickness = \"4 um\"\n";
    EXPECT_NE(error_of(electrode).find("t/g = 0.2"), std::string::npos) << error_of(electrode);
    EXPECT_EQ(error_of(thick + electrode), "");
}

// summary.json's resolved beam: each section as the model took it (width, thickness, EI, rho A,
// neutral axis) and the beam's mass; a plain beam lists none.
TEST(SectionsEstimates, SummaryListsTheSections) {
    const std::string run = "[[supports]]\nposition = 1\ngap = \"0.5 um\"\nstiffness = \"50 N/m\"\n"
                            "[initial]\nkind = \"displacement\"\ndisplacement = \"1 um\"\n"
                            "[solver]\nmethod = \"exact\"\nhorizon = \"20 us\"\n";
    const Case c = with(kStepped + run);
    const SimulationRun r = run_simulation(c);
    const nlohmann::json j = resolved_case_json(c, r.built, r.summary);
    ASSERT_EQ(j["beam"]["sections"].size(), 2u);
    const double E = 200e9, rho = 8900.0;
    EXPECT_DOUBLE_EQ(j["beam"]["sections"][1]["width_m"].get<double>(), 15e-6);
    EXPECT_DOUBLE_EQ(j["beam"]["sections"][1]["thickness_m"].get<double>(), 1.2e-6);
    EXPECT_LT(rel(j["beam"]["sections"][0]["EI_n_m2"].get<double>(), E * 30e-6 * 64e-18 / 12.0), 1e-14);
    EXPECT_LT(rel(j["beam"]["sections"][1]["rho_A_kg_m"].get<double>(), rho * 15e-6 * 1.2e-6), 1e-14);
    EXPECT_LT(rel(j["beam"]["mass_kg"].get<double>(), rho * (30e-6 * 4e-6 * 40e-6 + 15e-6 * 1.2e-6 * 60e-6)), 1e-14);
    const SimulationRun p = run_simulation(with(run));
    const nlohmann::json plain = resolved_case_json(with(run), p.built, p.summary);
    EXPECT_FALSE(plain["beam"].contains("sections"));
    EXPECT_LT(rel(plain["beam"]["mass_kg"].get<double>(), rho * 30e-6 * 2e-6 * 100e-6), 1e-14);
}

// A Hertz dimple on a layered section meets the layer facing it: the bottom one for a support below,
// the top one above (1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 with that layer's E1, nu1).
TEST(SectionsEstimates, HertzContactMeetsTheFacingLayer) {
    const std::string stack =
        "[[materials]]\nname = \"nitride\"\nyoungs_modulus = \"250 GPa\"\ndensity = \"3100 kg/m^3\"\npoisson_ratio = 0.23\n"
        "[[materials]]\nname = \"gold\"\nyoungs_modulus = \"79 GPa\"\ndensity = \"19300 kg/m^3\"\npoisson_ratio = 0.42\n"
        "[[beam.sections]]\nfrom = 0\nto = 1\n"
        "layers = [{ material = \"nitride\", thickness = \"0.5 um\" }, { material = \"gold\", thickness = \"1.5 um\" }]\n"
        "[solver]\nmethod = \"cvode\"\n";
    const auto force = [&](const char* side, double v) {
        const Case c = with(stack + "[[supports]]\nposition = 1.0\nside = \"" + side + "\"\ngap = \"0.1 um\"\n"
                            "law = \"hertz\"\nradius = \"2 um\"\nyoungs_modulus = \"100 GPa\"\npoisson_ratio = 0.3\n");
        const BeamModel b = build_beam_model(c);
        for (const auto& f : b.forces) {
            if (f->name() != "supports[0]") continue;
            const std::vector<double> q(f->dofs().size(), v), zero(f->dofs().size(), 0.0);
            std::vector<double> out(f->dofs().size(), 0.0);
            f->add_force(ElementState{0.0, q.data(), zero.data(), zero.data()}, 1, out.data());  // mode 1: closed
            double largest = 0.0;
            for (double x : out) largest = std::max(largest, std::abs(x));
            return largest;
        }
        return -1.0;
    };
    const double d = 0.1e-6, r = 2e-6;
    const double below = hertz_stiffness(effective_modulus(250e9, 0.23, 100e9, 0.3), r) * std::pow(d, 1.5);
    const double above = hertz_stiffness(effective_modulus(79e9, 0.42, 100e9, 0.3), r) * std::pow(d, 1.5);
    EXPECT_NEAR(force("below", -0.2e-6), below, 1e-9 * below);
    EXPECT_NEAR(force("above", 0.2e-6), above, 1e-9 * above);
}

}  // namespace
}  // namespace sections_estimates_test
}  // namespace vi
