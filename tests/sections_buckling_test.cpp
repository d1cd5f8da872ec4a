// The buckling rule of a beam of sections held at both ends (fem/buckling.hpp,
// problem/buckling_check.hpp): the finite-element buckling force of a uniform beam against Euler's
// load, a stepped beam's between those of its narrow and wide sections alone, and the refusal of a
// layer stress at or beyond it (exit 2 naming the material's key), a stress below it accepted.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "case_text_fixture.hpp"
#include "fem/buckling.hpp"
#include "fem/system.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "support/input_error_of.hpp"

namespace vi {
namespace sections_buckling_test {
namespace {

// The base case (l = 100 um, w = 30 um, t = 2 um, E = 200 GPa) held at both ends by `ends`, with
// `extra` appended.
Case held(const std::string& ends, const std::string& extra, int elements = 40) {
    std::string text = test::kBaseCase;
    text.replace(text.find("elements = 20"), 13, "elements = " + std::to_string(elements) + "\n" + ends);
    return read_case_text(text + extra, "buckling.toml");
}

const std::string kClamped = "left = \"clamped\"\nright = \"clamped\"";
const std::string kPinned = "left = \"pinned\"\nright = \"pinned\"";

std::string nitride(const std::string& stress) {
    return "[[materials]]\nname = \"nitride\"\nyoungs_modulus = \"200 GPa\"\ndensity = \"3100 kg/m^3\"\n"
           "poisson_ratio = 0.3\nresidual_stress = \"" + stress + "\"\n";
}

// Two sections of nitride: 30 um wide over the middle half, 10 um at the ends, both 2 um thick.
std::string stepped(const std::string& stress) {
    const std::string layer = "layers = [{ material = \"nitride\", thickness = \"2 um\" }]\n";
    return nitride(stress) + "[[beam.sections]]\nfrom = 0\nto = 0.25\nwidth = \"10 um\"\n" + layer +
           "[[beam.sections]]\nfrom = 0.25\nto = 0.75\nwidth = \"30 um\"\n" + layer +
           "[[beam.sections]]\nfrom = 0.75\nto = 1\nwidth = \"10 um\"\n" + layer;
}

// A uniform beam written as one section: n^2 pi^2 EI / l^2 with n = 1 pinned, 2 clamped; the Ritz
// bound lies above by O(h^4) of the cubic elements (m = 40: well under 1e-6).
TEST(SectionsBuckling, UniformBeamBucklesAtEulersLoad) {
    const std::string one = "[[beam.sections]]\nfrom = 0\nto = 1\n";
    const double EI = 200e9 * 30e-6 * 8e-18 / 12.0, l = 100e-6;
    const double pinned = buckling_force(build_system(held(kPinned, one)));
    const double clamped = buckling_force(build_system(held(kClamped, one)));
    const double euler = std::numbers::pi * std::numbers::pi * EI / (l * l);
    EXPECT_GE(pinned, euler * (1.0 - 1e-12));
    EXPECT_NEAR(pinned, euler, 1e-6 * euler);
    EXPECT_GE(clamped, 4.0 * euler * (1.0 - 1e-12));
    EXPECT_NEAR(clamped, 4.0 * euler, 1e-6 * 4.0 * euler);
}

// The stepped beam buckles above the all-narrow beam and below the all-wide one (EI between them
// everywhere), and its axial stress does not move the buckling force it is measured against.
TEST(SectionsBuckling, SteppedBeamBetweenItsSections) {
    const double EI_narrow = 200e9 * 10e-6 * 8e-18 / 12.0, l = 100e-6;
    const double p = buckling_force(build_system(held(kClamped, stepped("0 MPa"))));
    const double narrow = 4.0 * std::numbers::pi * std::numbers::pi * EI_narrow / (l * l);
    EXPECT_GT(p, 1.2 * narrow);
    EXPECT_LT(p, 3.0 * narrow);
    EXPECT_NEAR(buckling_force(build_system(held(kClamped, stepped("-1 MPa")))), p, 1e-9 * p);
}

std::string error_of(const std::string& ends, const std::string& extra) {
    return test::input_error_of([&] { held(ends, extra); });
}

// The held force is linear in the layer stress: N(sigma) = sigma N(1 Pa). At 1.02 times the buckling
// force the case is refused, naming the material's stress and both forces; at 0.98 it is read.
TEST(SectionsBuckling, CompressionAtBucklingIsRefused) {
    const System s = build_system(held(kClamped, stepped("1 MPa")));
    const double per_pa = s.axial_force / 1e6, p = buckling_force(s);
    const auto stress = [&](double ratio) { return std::to_string(-ratio * p / per_pa) + " Pa"; };
    EXPECT_EQ(error_of(kClamped, stepped(stress(0.98))), "");
    const std::string refused = error_of(kClamped, stepped(stress(1.02)));
    EXPECT_NE(refused.find("buckling.toml:18: materials[0].residual_stress: the sections' residual stresses compress "
                           "the beam held at both ends"),
              std::string::npos)
        << refused;
    EXPECT_NE(refused.find("1.02 times it"), std::string::npos) << refused;
    // A cantilever carries no axial force: the same stress is read.
    EXPECT_EQ(error_of("left = \"clamped\"\nright = \"free\"", stepped(stress(1.02))), "");
}

// Unlayered sections take beam.residual_stress: its compression beyond the stepped beam's load
// names that key.
TEST(SectionsBuckling, UnlayeredSectionsNameTheBeamStress) {
    const std::string sections = "[[beam.sections]]\nfrom = 0\nto = 0.5\nthickness = \"1 um\"\n"
                                 "[[beam.sections]]\nfrom = 0.5\nto = 1\n";
    const std::string refused = error_of(kClamped + "\nresidual_stress = \"-200 MPa\"", sections);
    EXPECT_NE(refused.find("beam.residual_stress: the sections' residual stresses compress"), std::string::npos)
        << refused;
    EXPECT_EQ(error_of(kClamped + "\nresidual_stress = \"-20 MPa\"", sections), "");
}

}  // namespace
}  // namespace sections_buckling_test
}  // namespace vi
