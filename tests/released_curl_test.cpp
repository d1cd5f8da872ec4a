// `modes` reports the released (curled) shape (modal/released_curl.hpp): a cantilever with a
// stress gradient against kappa0 x^2 / 2 (tip lift Gamma l^2 / (2 E)), a bilayer against
// Timoshenko's bimetal strip, a stepped cantilever of two curls against the piecewise arc, and the
// shape in modes.json, released_shape.csv and the printed summary; none for a straight beam or one
// clamped at both ends.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case_text_fixture.hpp"
#include "io/case_reader.hpp"
#include "modal/modal_analysis.hpp"
#include "report/modal_output.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace released_curl_test {
namespace {

// The base case (l = 100 um, w = 30 um, t = 2 um, E = 200 GPa) with `extra` appended.
Case with(const std::string& extra) { return read_case_text(test::kBaseCase + extra, "curl.toml"); }

std::string material(const char* name, const char* e, const char* stress, const char* gradient) {
    return std::string("[[materials]]\nname = \"") + name + "\"\nyoungs_modulus = \"" + e +
           "\"\ndensity = \"10000 kg/m^3\"\npoisson_ratio = 0.3\nresidual_stress = \"" + stress +
           "\"\nstress_gradient = " + gradient + "\n";
}

// kappa0 = Gamma / E: v = kappa0 x^2 / 2 and theta = kappa0 x at every node (the cubic elements
// hold the arc exactly), tip lift Gamma l^2 / (2 E).
TEST(ReleasedCurl, GradientCantileverIsTheClosedFormArc) {
    const double gamma = 2e13, E = 200e9, l = 100e-6, kappa = gamma / E;
    const ModalStudy s = modal_study(with("[curl]\nstress_gradient = 2e13\n"), 2, SupportModel::pin);
    ASSERT_TRUE(s.released);
    const ReleasedCurl& r = *s.released;
    EXPECT_NEAR(r.tip_lift, gamma * l * l / (2.0 * E), 1e-10 * r.tip_lift);
    EXPECT_EQ(r.largest, r.tip_lift);
    EXPECT_EQ(r.largest_at, 1.0);
    for (std::size_t k = 0; k < r.x.size(); ++k) {
        EXPECT_NEAR(r.v[k], 0.5 * kappa * r.x[k] * r.x[k], 1e-10 * r.tip_lift) << k;
        EXPECT_NEAR(r.theta[k], kappa * r.x[k], 1e-10 * kappa * l) << k;
    }
}

// Timoshenko's bimetal strip (J. Opt. Soc. Am. 11 (1925) 233): a nitride-gold bilayer as one
// section; tip lift kappa l^2 / 2.
TEST(ReleasedCurl, BilayerTipLiftIsTimoshenkos) {
    const double e1 = 160e9, e2 = 79e9, t1 = 0.5e-6, t2 = 1.5e-6, s1 = -200e6, s2 = 120e6, l = 100e-6;
    const Case c = with(material("nitride", "160 GPa", "-200 MPa", "0") + material("gold", "79 GPa", "120 MPa", "0") +
                        "[[beam.sections]]\nfrom = 0\nto = 1\nlayers = [{ material = \"nitride\", thickness = \"0.5 um\" }, "
                        "{ material = \"gold\", thickness = \"1.5 um\" }]\n");
    const double m = t1 / t2, n = e1 / e2, h = t1 + t2, d = -s1 / e1 + s2 / e2;
    const double kappa = 6.0 * d * (1 + m) * (1 + m) / (h * (3 * (1 + m) * (1 + m) + (1 + m * n) * (m * m + 1 / (m * n))));
    const ModalStudy s = modal_study(c, 2, SupportModel::pin);
    ASSERT_TRUE(s.released);
    EXPECT_NEAR(s.released->tip_lift, 0.5 * kappa * l * l, 1e-9 * 0.5 * kappa * l * l);
}

// Two sections of different gradients curl by kappa_i = Gamma_i / E_i each: the arc k1 x^2 / 2 to
// x = a, then k1 a^2 / 2 + k1 a (x - a) + k2 (x - a)^2 / 2.
TEST(ReleasedCurl, SteppedCantileverIsThePiecewiseArc) {
    const Case c = with(material("p", "150 GPa", "0 MPa", "1.5e13") + material("q", "100 GPa", "0 MPa", "-4e12") +
                        "[[beam.sections]]\nfrom = 0\nto = 0.4\nlayers = [{ material = \"p\", thickness = \"2 um\" }]\n"
                        "[[beam.sections]]\nfrom = 0.4\nto = 1\nwidth = \"15 um\"\n"
                        "layers = [{ material = \"q\", thickness = \"1 um\" }]\n");
    const double k1 = 1.5e13 / 150e9, k2 = -4e12 / 100e9, a = 40e-6;
    const auto arc = [&](double x) {
        return x <= a ? 0.5 * k1 * x * x : 0.5 * k1 * a * a + k1 * a * (x - a) + 0.5 * k2 * (x - a) * (x - a);
    };
    const ModalStudy s = modal_study(c, 2, SupportModel::pin);
    ASSERT_TRUE(s.released);
    const ReleasedCurl& r = *s.released;
    const double scale = std::abs(arc(a));
    for (std::size_t k = 0; k < r.x.size(); ++k) EXPECT_NEAR(r.v[k], arc(r.x[k]), 1e-9 * scale) << k;
    EXPECT_NEAR(r.tip_lift, arc(100e-6), 1e-9 * scale);
}

// The paddle switch example (titanium under gold, 1.5 um of gold on the flexures to x/l = 0.3, 2 um
// beyond): each stack's kappa = M_r / EI from its transformed section, computed here apart, and the
// piecewise arc's tip, 0.7403 um.
TEST(ReleasedCurl, PaddleSwitchTipIsThePiecewiseArcOfItsStacks) {
    const auto kappa = [](double gold) {
        const double e[2] = {116e9, 79e9}, t[2] = {50e-9, gold}, sigma[2] = {50e6, 20e6}, grad[2] = {0.0, 8e12};
        const double axis = (e[0] * t[0] * 0.5 * t[0] + e[1] * t[1] * (t[0] + 0.5 * t[1])) / (e[0] * t[0] + e[1] * t[1]);
        double EI = 0.0, M = 0.0, z = 0.0;
        for (int k = 0; k < 2; ++k) {
            const double arm = z + 0.5 * t[k] - axis;
            EI += e[k] * (t[k] * t[k] * t[k] / 12.0 + t[k] * arm * arm);
            M += sigma[k] * t[k] * arm + grad[k] * t[k] * t[k] * t[k] / 12.0;
            z += t[k];
        }
        return M / EI;  // per unit width: the width cancels
    };
    const double l = 150e-6, a = 0.3 * l, k1 = kappa(1.5e-6), k2 = kappa(2e-6);
    const double tip = 0.5 * k1 * a * a + k1 * a * (l - a) + 0.5 * k2 * (l - a) * (l - a);
    const ModalStudy s = modal_study(read_case_file(test::source_path("examples/devices/ohmic_paddle_switch.toml")), 1,
                                     SupportModel::pin);
    ASSERT_TRUE(s.released);
    // The static solve of 60 elements over stacks 4.5 times apart in width keeps about 8 digits.
    EXPECT_NEAR(s.released->tip_lift, tip, 1e-7 * tip);
    EXPECT_NEAR(tip, 0.7403e-6, 1e-10);
}

TEST(ReleasedCurl, NoneForAStraightOrClampedBeam) {
    EXPECT_FALSE(modal_study(with(""), 2, SupportModel::pin).released);
    std::string text = test::kBaseCase;
    text.replace(text.find("elements = 20"), 13, "elements = 20\nleft = \"clamped\"\nright = \"clamped\"");
    EXPECT_FALSE(modal_study(read_case_text(text + "[curl]\nstress_gradient = 2e13\n", "cc.toml"), 2, SupportModel::pin).released);
}

// modes.json's `released`, released_shape.csv (x_over_l, x_m, v_m, theta_rad at each node) and the
// summary's line; a straight beam writes neither.
TEST(ReleasedCurl, WrittenByModes) {
    const ModalStudy s = modal_study(with("[curl]\ntip_lift = \"0.5 um\"\n"), 2, SupportModel::pin);
    const nlohmann::json j = modal_study_json(s);
    ASSERT_TRUE(j.contains("released"));
    EXPECT_NEAR(j["released"]["tip_lift_m"].get<double>(), 0.5e-6, 1e-9 * 0.5e-6);
    EXPECT_EQ(j["released"]["nodes"]["v_m"].size(), 21u);
    const OutputFiles files = modal_study_files(s);
    ASSERT_EQ(files.count("released_shape.csv"), 1u);
    const std::string& csv = files.at("released_shape.csv");
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "x_over_l,x_m,v_m,theta_rad");
    EXPECT_NE(modal_study_text(s).find("Released shape at rest (the curl): tip lift 0.5 um, largest lift 0.5 um at x/l = 1"),
              std::string::npos)
        << modal_study_text(s);
    const ModalStudy straight = modal_study(with(""), 2, SupportModel::pin);
    EXPECT_FALSE(modal_study_json(straight).contains("released"));
    EXPECT_EQ(modal_study_files(straight).count("released_shape.csv"), 0u);
}

}  // namespace
}  // namespace released_curl_test
}  // namespace vi
