// Perforated sections (a section's `holes`; fem/section_properties.hpp, forces/perforated_film.hpp):
// the stiffness and mass factors against the ligament efficiency and the solid fraction, a
// perforated cantilever's and bridge's first frequencies against the uniform Euler-Bernoulli beam
// with the effective EI and rho A, the electrode's force and capacitance over the solid fraction, the
// perforated film against Skvor's cell result (plus the hole's Poiseuille-Sampson resistance) at two
// hole ratios and against a finite-difference solution of its own equation across the width, the
// written case, and the refusals of bad holes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "case_text_fixture.hpp"
#include "fem/section_properties.hpp"
#include "fem/system.hpp"
#include "forces/perforated_film.hpp"
#include "forces/squeeze_film.hpp"
#include "io/case_reader.hpp"
#include "io/case_writer.hpp"
#include "modal/eigen_solver.hpp"
#include "model/input_error.hpp"
#include "problem/beam_model.hpp"
#include "statics/layer_hold.hpp"
#include "sweep/case_paths.hpp"
#include "support/rest_force.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "support/input_error_of.hpp"

namespace vi {
namespace perforated_test {

constexpr double kEps0 = 8.8541878128e-12;

// The base case (l = 100 um, w = 30 um, t = 2 um, E = 200 GPa, rho = 8900, clamped-free, m = 20)
// with extra text after its [material] table.
Case base_with(const std::string& extra, const std::string& ends = "") {
    std::string text = test::kBaseCase;
    if (!ends.empty()) text.insert(text.find("elements = 20\n") + 14, ends);
    return read_case_text(text + extra, "holes.toml");
}

std::string holed(const char* holes) {
    return std::string("[[beam.sections]]\nfrom = 0\nto = 1\nholes = ") + holes + "\n";
}

double lowest_frequency(const Case& c) {
    const System s = build_system(c, SupportModel::none);
    return lowest_modes(submatrix(s.K, s.bending), submatrix(s.M, s.bending), 1).omega[0];
}

// mu = 1 - s/p on EI and EA; the solid fraction 1 - (s/p)^2 (square) or 1 - (pi/4)(s/p)^2 (round) on
// rho A and on the electrode's area; the section's resultants are the solid ones times these.
TEST(PerforatedSections, FactorsAreTheLigamentEfficiencyAndTheSolidFraction) {
    const SectionFactors sq = hole_factors({5e-6, 10e-6, HoleShape::square});
    EXPECT_DOUBLE_EQ(sq.stiffness, 0.5);
    EXPECT_DOUBLE_EQ(sq.mass, 0.75);
    EXPECT_DOUBLE_EQ(sq.area, 0.75);
    const SectionFactors ci = hole_factors({8e-6, 20e-6, HoleShape::circle});
    EXPECT_DOUBLE_EQ(ci.stiffness, 0.6);
    EXPECT_NEAR(ci.mass, 1.0 - 0.25 * std::numbers::pi * 0.16, 1e-15);
    const Case c = base_with(holed("{ size = \"6 um\", pitch = \"10 um\" }"));
    const SectionResultants r = section_resultants(c, 0);
    const double w = 30e-6, t = 2e-6;
    EXPECT_NEAR(r.EI, 0.4 * 200e9 * w * t * t * t / 12.0, 1e-12 * r.EI);
    EXPECT_NEAR(r.EA, 0.4 * 200e9 * w * t, 1e-12 * r.EA);
    EXPECT_NEAR(r.rho_A, 0.64 * 8900.0 * w * t, 1e-12 * r.rho_A);
    EXPECT_DOUBLE_EQ(r.solid_fraction, 0.64);
    // A solid section is untouched.
    EXPECT_EQ(section_resultants(base_with("[[beam.sections]]\nfrom = 0\nto = 1\n"), 0).EI, plain_section(c).EI);
}

// A cantilever and a clamped-clamped bridge perforated along their whole length: their first
// frequency is the uniform beam's, lambda^2 sqrt(EI* / (rho A* l^4)), with EI* = mu E I and
// rho A* = (1 - r^2) rho A (lambda = 1.8751040687 and 4.7300407449), to the FE model's discretisation
// at m = 20 (a factor applied wrongly moves them by tens of percent).
TEST(PerforatedSections, FirstFrequencyIsTheUniformBeamsWithTheEffectiveEIAndRhoA) {
    const double l = 100e-6, w = 30e-6, t = 2e-6;
    const double ei = 0.4 * 200e9 * w * t * t * t / 12.0, rho_a = 0.64 * 8900.0 * w * t;
    const double base = std::sqrt(ei / (rho_a * l * l * l * l));
    const Case cantilever = base_with(holed("{ size = \"6 um\", pitch = \"10 um\", shape = \"square\" }"));
    const double lc = 1.8751040687;
    EXPECT_NEAR(lowest_frequency(cantilever), lc * lc * base, 1e-7 * lc * lc * base);
    const Case bridge = base_with(holed("{ size = \"6 um\", pitch = \"10 um\" }"), "right = \"clamped\"\n");
    const double lb = 4.7300407449;
    // The bridge's m = 20 discretisation error is 2.2e-6 (the cantilever's below 1e-7).
    EXPECT_NEAR(lowest_frequency(bridge), lb * lb * base, 3e-6 * lb * lb * base);
    // Round holes of the same size leave more: mu is the same, the mass more (1 - 0.09 pi), so the
    // frequency falls by sqrt(0.64 / (1 - 0.09 pi)).
    const Case round = base_with(holed("{ size = \"6 um\", pitch = \"10 um\", shape = \"circle\" }"));
    const double expected = lc * lc * base * std::sqrt(0.64 / (1.0 - 0.09 * std::numbers::pi));
    EXPECT_NEAR(lowest_frequency(round), expected, 1e-7 * expected);
}

const ForceElement* named(const BeamModel& b, const std::string& name) {
    for (const auto& f : b.forces) {
        if (f->name() == name) return f.get();
    }
    return nullptr;
}

// An electrode under a perforated section and a solid one: at rest its force is eps0 V^2 / (2 g^2)
// times the solid area it faces, and its capacitance eps0 times that area over g.
TEST(PerforatedSections, ElectrodeFacesTheSolidFractionOfItsArea) {
    const Case c = base_with(
        "[[beam.sections]]\nfrom = 0\nto = 0.5\nholes = { size = \"5 um\", pitch = \"10 um\" }\n"
        "[[beam.sections]]\nfrom = 0.5\nto = 1\n"
        "[[electrodes]]\nfrom = 0.2\nto = 0.9\ngap = \"2 um\"\nvoltage = \"10 V\"\nwaveform = \"step\"\nt_on = \"0 us\"\n");
    const BeamModel b = build_beam_model(c);
    const auto* pad = dynamic_cast<const ElectrostaticPad*>(named(b, "electrodes[0]"));
    ASSERT_NE(pad, nullptr);
    const std::vector<double> q(pad->dofs().size(), 0.0);
    const double total = test::rest_force(b, "electrodes[0]", 1e-9);
    const double l = 100e-6, g = 2e-6, area = 30e-6 * (0.75 * 0.3 * l + 0.4 * l);
    const double expected = -kEps0 * 100.0 / (2.0 * g * g) * area;
    EXPECT_NEAR(total, expected, 1e-12 * std::abs(expected));
    EXPECT_NEAR(pad->capacitance(q.data()), kEps0 * area / g, 1e-12 * kEps0 * area / g);
}

const FilmGas kAir{1.85e-5, 68e-9};

// Skvor's cell (the gap flow toward the hole) in series with the hole (Poiseuille through the
// plate, Sampson's orifice at its ends), written here from the closed forms: the damping per unit
// area of an unbounded perforated plate [N s/m^3].
double unbounded_plate_damping(double r0, double pitch, double plate, double gap, bool circle, double size) {
    const double rc = pitch / std::sqrt(std::numbers::pi), beta = r0 / rc;
    const double mu_eff = kAir.viscosity / veijola_factor(kAir.mean_free_path / gap);
    const double k = 4.0 * beta * beta - std::pow(beta, 4) - 4.0 * std::log(beta) - 3.0;
    const double gap_part = 3.0 * std::numbers::pi * mu_eff * std::pow(rc, 4) * k / (2.0 * gap * gap * gap);
    const double tube = circle ? 8.0 * kAir.viscosity * plate / (std::numbers::pi * std::pow(r0, 4))
                               : 56.91 / 2.0 * kAir.viscosity * plate / std::pow(size, 4);
    const double hole = tube + 3.0 * kAir.viscosity / (r0 * r0 * r0);
    // Each cell pushes its moving area's flow pi (rc^2 - r0^2) v through the hole, whose pressure
    // acts on the whole cell (the plate's face and the hole's wall).
    const double hole_part = hole * std::numbers::pi * (rc * rc - r0 * r0) * std::numbers::pi * rc * rc;
    return (gap_part + hole_part) / (pitch * pitch);
}

// A strip so wide (z ~ 1e5) that its vented edges do not matter: its damping per unit area is the
// unbounded plate's at two hole ratios (beta = 0.3 round, 0.5 square holes), to the edge term 2 / z.
TEST(PerforatedSections, WideStripIsSkvorsCellInSeriesWithItsHole) {
    const double gap = 3e-6, plate = 2e-6, width = 0.5;
    for (const bool circle : {true, false}) {
        const double pitch = 20e-6;
        const double beta = circle ? 0.3 : 0.5;
        const double rc = pitch / std::sqrt(std::numbers::pi), r0 = beta * rc;
        const double size = circle ? 2.0 * r0 : r0 * std::sqrt(std::numbers::pi);
        const FilmPerforation p{size, pitch, circle, plate, width};
        const FilmCoefficient solid = film_coefficient(kAir, width, gap);
        const PerforationFactor f = perforation_factor(p, kAir, gap, solid.dc / solid.c);
        const double per_area = solid.c * f.value / width;
        const double expected = unbounded_plate_damping(r0, pitch, plate, gap, circle, size);
        std::printf("perforated plate beta = %.1f (%s): %.6g N s/m^3, closed form %.6g\n", beta,
                    circle ? "round" : "square", per_area, expected);
        EXPECT_NEAR(per_area, expected, 1e-4 * expected);
    }
}

// The strip's own equation across the width, (1 / 12 a) P'' - P / (A_c R) = -(1 - beta^2) v with P = 0
// at the edges, solved by central differences on 4000 intervals: its force per length against the
// closed form, for a strip of 5 and of 40 holes across.
TEST(PerforatedSections, StripFactorIsTheSolutionOfTheModifiedReynoldsEquation) {
    const double gap = 2e-6, pitch = 15e-6, size = 6e-6, plate = 1.5e-6;
    for (const double width : {75e-6, 600e-6}) {
        const FilmPerforation p{size, pitch, false, plate, width};
        const FilmCoefficient solid = film_coefficient(kAir, width, gap);
        const double c = solid.c * perforation_factor(p, kAir, gap, solid.dc / solid.c).value;
        const double mu_eff = kAir.viscosity / veijola_factor(kAir.mean_free_path / gap);
        const double a = mu_eff / (gap * gap * gap);
        const PerforationCell cell = perforation_cell(p);
        const double beta = cell.hole_radius / cell.cell_radius;
        const double r = hole_resistance(p, kAir.viscosity) +
                         3.0 * a * skvor_function(beta) / (2.0 * std::numbers::pi * (1.0 - beta * beta));
        const double sink = 12.0 * a / (pitch * pitch * r), source = 12.0 * a * (1.0 - beta * beta);
        const int n = 4000;
        const double h = width / n;
        // Tridiagonal (Thomas) solve of -P'' + sink P = source at the n - 1 inner nodes.
        std::vector<double> diag(n - 1, 2.0 / (h * h) + sink), rhs(n - 1, source);
        const double off = -1.0 / (h * h);
        for (int i = 1; i < n - 1; ++i) {
            const double m = off / diag[static_cast<std::size_t>(i - 1)];
            diag[static_cast<std::size_t>(i)] -= m * off;
            rhs[static_cast<std::size_t>(i)] -= m * rhs[static_cast<std::size_t>(i - 1)];
        }
        std::vector<double> pr(n - 1);
        pr[static_cast<std::size_t>(n - 2)] = rhs[static_cast<std::size_t>(n - 2)] / diag[static_cast<std::size_t>(n - 2)];
        for (int i = n - 3; i >= 0; --i) {
            pr[static_cast<std::size_t>(i)] =
                (rhs[static_cast<std::size_t>(i)] - off * pr[static_cast<std::size_t>(i + 1)]) / diag[static_cast<std::size_t>(i)];
        }
        double force = 0.0;  // trapezoid rule, P = 0 at both edges
        for (const double v : pr) force += v * h;
        std::printf("perforated strip w = %.0f um: %.8g N s/m^2, finite differences %.8g\n", width * 1e6, c, force);
        EXPECT_NEAR(c, force, 2e-6 * force);
        EXPECT_LT(c, solid.c);
    }
}

// The factor and its slope: the series and the closed form of F(z) meet at z = 0.2; the slope the
// element's tangent uses is the derivative of the value (central differences in the gap).
TEST(PerforatedSections, FactorSlopeIsItsDerivative) {
    const StripFactor below = strip_factor(0.04 * (1.0 - 1e-12)), above = strip_factor(0.04 * (1.0 + 1e-12));
    EXPECT_NEAR(below.value, above.value, 1e-12);
    EXPECT_NEAR(below.slope, above.slope, 1e-10);
    EXPECT_NEAR(strip_factor(1e-8).value, 1.0, 1e-9);
    for (const double width : {20e-6, 100e-6}) {
        const FilmPerforation p{8e-6, 18e-6, true, 2e-6, width};
        for (const double gap : {0.2e-6, 3e-6}) {
            const FilmCoefficient s = film_coefficient(kAir, width, gap);
            const PerforationFactor f = perforation_factor(p, kAir, gap, s.dc / s.c);
            const double d = 1e-6 * gap;
            const FilmCoefficient sp = film_coefficient(kAir, width, gap + d), sm = film_coefficient(kAir, width, gap - d);
            const double fd = (perforation_factor(p, kAir, gap + d, sp.dc / sp.c).value -
                               perforation_factor(p, kAir, gap - d, sm.dc / sm.c).value) / (2.0 * d);
            EXPECT_NEAR(f.slope, fd, 1e-6 * std::abs(fd) + 1e-9 / gap) << width << " " << gap;
            EXPECT_GT(f.value, 0.0);
            EXPECT_LT(f.value, 1.0);
        }
    }
}

// A film under a perforated section and a solid one: at the gap at rest, a uniform unit velocity
// dissipates the perforated strip's c over the holed length and the solid strip's over the rest.
TEST(PerforatedSections, FilmVentsThroughTheHolesOfTheSectionOverIt) {
    const Case c = base_with(
        "[[beam.sections]]\nfrom = 0\nto = 0.5\nholes = { size = \"5 um\", pitch = \"10 um\", shape = \"circle\" }\n"
        "[[beam.sections]]\nfrom = 0.5\nto = 1\n[air]\n[[films]]\nfrom = 0.2\nto = 0.9\ngap = \"2 um\"\n");
    const BeamModel b = build_beam_model(c);
    const ForceElement* film = named(b, "films[0]");
    ASSERT_NE(film, nullptr);
    const std::vector<double> q(film->dofs().size(), 0.0);
    std::vector<double> v(film->dofs().size(), 0.0);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = b.is_v[static_cast<std::size_t>(film->dofs()[i])] ? 1.0 : 0.0;
    const double power = film->dissipated_power(ElementState{0.0, q.data(), v.data(), q.data()}, 0);
    const FilmGas gas{c.air->viscosity, c.air->lambda()};
    const FilmCoefficient solid = film_coefficient(gas, 30e-6, 2e-6);
    const double factor = perforation_factor({5e-6, 10e-6, true, 2e-6, 30e-6}, gas, 2e-6, solid.dc / solid.c).value;
    const double l = 100e-6;
    const double expected = solid.c * factor * 0.3 * l + solid.c * 0.4 * l;
    EXPECT_NEAR(power, expected, 1e-12 * expected);
    EXPECT_LT(factor, 0.75);
}

// A perforated cantilever (mu = 0.5, solid fraction 0.75) held on an electrode's adhesive layer: the
// layer touches only the solid fraction of its width, so W = w w_e 0.75, and the peel balance is the
// clamped-guided span's with mu E I: the detached length (18 mu E I h^2 / W)^(1/4) and the critical
// work of adhesion 1.5 mu E t^3 h^2 / (0.75 l^4) (docs/adhesion.md §10).
TEST(PerforatedSections, LayerHoldTouchesTheSolidFractionOfTheLayer) {
    const double E = 200e9, t = 2e-6, we = 30e-6, l = 100e-6, h = 1.5e-6, w = 0.2, mu = 0.5, solid = 0.75;
    const Case c = base_with(holed("{ size = \"5 um\", pitch = \"10 um\" }") +
                             "[[electrodes]]\nfrom = 0.2\nto = 1.0\ngap = \"1.7 um\"\ndielectric_thickness = \"0.2 um\"\n"
                             "work_of_adhesion = 0.2\nvoltage = \"0 V\"\n");
    const double EI = mu * E * we * t * t * t / 12.0, W = w * we * solid;
    EXPECT_NEAR(layer_contact_width(c, 0), solid * we, 1e-15 * we);
    const LayerHold hold = layer_hold(c, 0);
    ASSERT_TRUE(hold.sticks);
    EXPECT_NEAR(hold.adhesion_energy, W, 1e-12 * W);
    const double ld = std::pow(18.0 * EI * h * h / W, 0.25);
    EXPECT_NEAR(hold.contact_from, ld, 1e-9 * ld);
    const double critical = 1.5 * mu * E * t * t * t * h * h / (solid * std::pow(l, 4));
    EXPECT_NEAR(hold.critical_work_of_adhesion, critical, 1e-9 * critical);
}

// The holes' size and pitch are paths (sweep, fit, optimisation): a value set through the path
// gives the model of the case file that writes it; a section without holes, a misspelt part and a
// size at or past the pitch are refused with the path and the reason.
TEST(PerforatedSections, HoleSizeAndPitchArePaths) {
    const Case base = base_with(holed("{ size = \"5 um\", pitch = \"10 um\" }"));
    Case swept = base;
    set_case_text(swept, "beam.sections[0].holes.size", "6 um");
    set_case_text(swept, "beam.sections[0].holes.pitch", "12.5 um");
    EXPECT_EQ(get_case_value(swept, resolve_case_path("beam.sections[0].holes.size", swept)), 6e-6);
    EXPECT_EQ(lowest_frequency(swept), lowest_frequency(base_with(holed("{ size = \"6 um\", pitch = \"12.5 um\" }"))));
    EXPECT_NE(lowest_frequency(swept), lowest_frequency(base));
    EXPECT_EQ(case_path_column(resolve_case_path("beam.sections[0].holes.pitch", swept)), "beam.sections[0].holes.pitch_m");
    const std::vector<std::string> forms = case_path_forms();
    EXPECT_NE(std::find(forms.begin(), forms.end(), "beam.sections[i].holes.size"), forms.end());

    const Case solid = base_with("[[beam.sections]]\nfrom = 0\nto = 1\n");
    EXPECT_EQ(test::input_error_of([&] { resolve_case_path("beam.sections[0].holes.size", solid); }),
              "beam.sections[0].holes.size: the section has no holes (give them in the case file to vary their size or "
              "pitch)");
    EXPECT_EQ(test::input_error_of([&] { resolve_case_path("beam.sections[0].holes.sise", base); }),
              "unknown key 'holes.sise' in beam.sections[i] (did you mean 'holes.size'?)");
    Case bad = base;
    EXPECT_EQ(test::input_error_of([&] { apply_case_settings(bad, "--set", {"beam.sections[0].holes.size=10um"}); }),
              "--set: beam.sections[0].holes.size: must be below the pitch (10 um): the holes would leave no material "
              "between them");
    EXPECT_EQ(test::input_error_of([&] { set_case_text(bad, "beam.sections[0].holes.pitch", "-1 um"); }),
              "beam.sections[0].holes.pitch: must be positive");
}

// Holes are written back and read the same (TOML and JSON).
TEST(PerforatedSections, WrittenCaseReadsBack) {
    const Case c = base_with(holed("{ size = \"7 um\", pitch = \"15 um\", shape = \"circle\" }"));
    const Case back = read_case_text(case_to_toml(c), "written.toml");
    ASSERT_TRUE(back.beam.sections[0].holes.has_value());
    EXPECT_EQ(back.beam.sections[0].holes->size, c.beam.sections[0].holes->size);
    EXPECT_EQ(back.beam.sections[0].holes->pitch, c.beam.sections[0].holes->pitch);
    EXPECT_EQ(back.beam.sections[0].holes->shape, HoleShape::circle);
    EXPECT_EQ(case_to_json(c)["beam"]["sections"][0]["holes"]["shape"], "circle");
    EXPECT_FALSE(read_case_text(case_to_toml(base_with(holed("{ size = \"7 um\", pitch = \"15 um\" }"))), "w.toml")
                     .beam.sections[0]
                     .holes->shape == HoleShape::circle);
}

std::string error_of(const std::string& holes, const std::string& width = "") {
    return test::input_error_of([&] { base_with("[[beam.sections]]\nfrom = 0\nto = 1\n" + width + "holes = " + holes + "\n"); });
}

// Holes as large as their pitch, wider than the section, of no size or pitch, of an unknown shape or
// with an unknown key: one line naming the file, the line and the key.
TEST(PerforatedSections, BadHolesAreRefusedAtTheirLine) {
    EXPECT_EQ(error_of("{ size = \"10 um\", pitch = \"10 um\" }"),
              "holes.toml:14: beam.sections[0].holes.size: must be below the pitch (10 um): the holes would leave no "
              "material between them");
    EXPECT_EQ(error_of("{ size = \"12 um\", pitch = \"40 um\" }", "width = \"10 um\"\n"),
              "holes.toml:15: beam.sections[0].holes.size: the holes (12 um) are as wide as the section or wider "
              "(w = 10 um): they would cut it");
    EXPECT_EQ(error_of("{ size = \"0 um\", pitch = \"10 um\" }"), "holes.toml:14: beam.sections[0].holes.size: must be positive");
    EXPECT_EQ(error_of("{ size = \"2 um\", pitch = \"-10 um\" }"), "holes.toml:14: beam.sections[0].holes.pitch: must be positive");
    EXPECT_NE(error_of("{ size = \"2 um\", pitch = \"10 um\", shape = \"hexagon\" }")
                  .find("holes.toml:14: beam.sections[0].holes.shape:"),
              std::string::npos);
    EXPECT_NE(error_of("{ size = \"2 um\", pitch = \"10 um\", spacing = \"1 um\" }").find("holes.toml:14: beam.sections[0].holes.spacing:"),
              std::string::npos);
    EXPECT_NE(error_of("{ pitch = \"10 um\" }").find("holes.toml:14: beam.sections[0].holes.size: missing"), std::string::npos)
        << error_of("{ pitch = \"10 um\" }");
    EXPECT_NE(error_of("\"5 um\"").find("holes.toml:14: beam.sections[0].holes:"), std::string::npos);
}

// From the command line: holes wider than the section exit 2 with that one line on stderr and
// nothing written.
TEST(PerforatedSections, CommandLineRefusesBadHolesWithExitTwo) {
    const std::string dir = test::make_temp_dir();
    std::string text = test::kBaseCase + "[[beam.sections]]\nfrom = 0\nto = 1\nholes = { size = \"40 um\", pitch = \"50 um\" }\n";
    test::write_text(dir + "/holes.toml", text);
    const auto r = test::run_vibroimpact({"modes", dir + "/holes.toml", "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "vibroimpact: error: " + dir + "/holes.toml:14: beam.sections[0].holes.size: the holes (40 um) are "
                     "as wide as the section or wider (w = 30 um): they would cut it\n");
    EXPECT_FALSE(std::filesystem::exists(dir + "/out"));
}

}  // namespace perforated_test
}  // namespace vi
