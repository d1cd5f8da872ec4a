// Beams of sections and layers ([[beam.sections]], [[materials]]; fem/section_properties.hpp): a
// stepped cantilever's frequencies against the exact ones of the segmented Euler-Bernoulli beam
// (its 8 x 8 determinant root-found here, an independent method), a uniform beam written as one
// section, two equal sections and one layer against the plain beam, a bilayer's released curvature
// against Timoshenko's bimetal formula, a layer's stress gradient against Gamma / E, the electrode's
// force over sections of two widths, the paths and written case, and the refusals of bad sections.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "case_text_fixture.hpp"
#include "fem/section_properties.hpp"
#include "impacts/simulation.hpp"
#include "fem/system.hpp"
#include "forces/squeeze_film.hpp"
#include "io/case_reader.hpp"
#include "io/case_writer.hpp"
#include "modal/eigen_solver.hpp"
#include "model/input_error.hpp"
#include "problem/beam_model.hpp"
#include "statics/static_solution.hpp"
#include "support/rest_force.hpp"
#include "support/test_files.hpp"
#include "sweep/case_paths.hpp"
#include "support/input_error_of.hpp"

namespace vi {
namespace sections_test {

// The base case (l = 100 um, w = 30 um, t = 2 um, E = 200 GPa, rho = 8900) with `elements` and extra
// text appended after its [material] table.
Case base_with(const std::string& extra, int elements = 20) {
    std::string text = test::kBaseCase;
    const auto at = text.find("elements = 20");
    text.replace(at, 13, "elements = " + std::to_string(elements));
    return read_case_text(text + extra, "sections.toml");
}

// The lowest `count` bending circular frequencies of c's beam [rad/s].
Eigen::VectorXd frequencies(const Case& c, int count) {
    const System s = build_system(c, SupportModel::none);
    return lowest_modes(submatrix(s.K, s.bending), submatrix(s.M, s.bending), count).omega;
}

// One segment of a segmented Euler-Bernoulli beam.
struct Segment {
    double length, EI, rho_A;
};

// det of the 8 x 8 system of a cantilever of two segments at circular frequency w: in segment i
// y = a cos(b s) + b' sin(b s) + c cosh(b s) + d sinh(b s), s from the segment's start,
// b^4 = w^2 rho_A / EI; rows: y, y' at the clamp; y, y', EI y'', EI y''' continuous at the step;
// EI y'', EI y''' zero at the free end.
double segmented_determinant(const std::vector<Segment>& seg, double w) {
    // Row vectors of y and its derivatives (order 0..3) of the four functions at s, with factor b^k.
    const auto row = [](double b, double s, int order) {
        const double c = std::cos(b * s), sn = std::sin(b * s), ch = std::cosh(b * s), sh = std::sinh(b * s);
        Eigen::RowVector4d r;
        switch (order) {
            case 0: r << c, sn, ch, sh; break;
            case 1: r << -sn, c, sh, ch; break;
            case 2: r << -c, -sn, ch, sh; break;
            default: r << sn, -c, sh, ch; break;
        }
        return Eigen::RowVector4d(r * std::pow(b, order));
    };
    const double b0 = std::pow(w * w * seg[0].rho_A / seg[0].EI, 0.25);
    const double b1 = std::pow(w * w * seg[1].rho_A / seg[1].EI, 0.25);
    Eigen::Matrix<double, 8, 8> a = Eigen::Matrix<double, 8, 8>::Zero();
    a.block<1, 4>(0, 0) = row(b0, 0.0, 0);
    a.block<1, 4>(1, 0) = row(b0, 0.0, 1);
    for (int k = 0; k < 4; ++k) {
        const double f0 = k >= 2 ? seg[0].EI : 1.0, f1 = k >= 2 ? seg[1].EI : 1.0;
        a.block<1, 4>(2 + k, 0) = f0 * row(b0, seg[0].length, k);
        a.block<1, 4>(2 + k, 4) = -f1 * row(b1, 0.0, k);
    }
    a.block<1, 4>(6, 4) = row(b1, seg[1].length, 2);
    a.block<1, 4>(7, 4) = row(b1, seg[1].length, 3);
    // Rows scaled to unit size, so that the sign changes are not lost to the EI factors.
    for (int r = 0; r < 8; ++r) a.row(r) /= a.row(r).cwiseAbs().maxCoeff();
    return a.determinant();
}

// The lowest `count` roots of the segmented determinant: a scan in small steps of w, then bisection.
std::vector<double> segmented_frequencies(const std::vector<Segment>& seg, int count, double w_max) {
    std::vector<double> roots;
    const int steps = 200000;
    double w_prev = w_max * 1e-6, d_prev = segmented_determinant(seg, w_prev);
    for (int i = 1; i <= steps && static_cast<int>(roots.size()) < count; ++i) {
        const double w = w_max * i / steps, d = segmented_determinant(seg, w);
        if ((d < 0.0) != (d_prev < 0.0)) {
            double lo = w_prev, hi = w;
            for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
                const double mid = 0.5 * (lo + hi);
                ((segmented_determinant(seg, mid) < 0.0) == (d_prev < 0.0) ? lo : hi) = mid;
            }
            roots.push_back(0.5 * (lo + hi));
        }
        w_prev = w;
        d_prev = d;
    }
    return roots;
}

const std::string kStepped =
    "[[beam.sections]]\nfrom = 0\nto = 0.4\nwidth = \"30 um\"\nthickness = \"2 um\"\n"
    "[[beam.sections]]\nfrom = 0.4\nto = 1\nwidth = \"15 um\"\nthickness = \"1.2 um\"\n";

// Exact frequencies of the stepped cantilever (a wide thick root, a narrow thin tip) against the FE
// model at m = 10, 20, 40, 80: the error of each of the first three modes falls with m (about as h^4
// for cubic elements with consistent mass) and is below 1e-7 at m = 80.
TEST(BeamSections, SteppedCantileverMatchesTheSegmentedBeamsExactFrequencies) {
    const double l = 100e-6, E = 200e9, rho = 8900.0;
    const std::vector<Segment> seg{{0.4 * l, E * 30e-6 * 8e-18 / 12.0, rho * 30e-6 * 2e-6},
                                   {0.6 * l, E * 15e-6 * 1.2e-6 * 1.2e-6 * 1.2e-6 / 12.0, rho * 15e-6 * 1.2e-6}};
    const Eigen::VectorXd coarse = frequencies(base_with(kStepped, 10), 3);
    const std::vector<double> exact = segmented_frequencies(seg, 3, 1.5 * coarse[2]);
    ASSERT_EQ(exact.size(), 3u);
    std::vector<double> previous(3, 1.0);
    for (const int m : {10, 20, 40, 80}) {
        const Eigen::VectorXd w = frequencies(base_with(kStepped, m), 3);
        for (int k = 0; k < 3; ++k) {
            const double error = std::abs(w[k] - exact[static_cast<std::size_t>(k)]) / exact[static_cast<std::size_t>(k)];
            std::printf("stepped cantilever m = %d mode %d: FE %.10g rad/s, exact %.10g rad/s, error %.2e\n", m, k + 1,
                        w[k], exact[static_cast<std::size_t>(k)], error);
            EXPECT_LT(error, previous[static_cast<std::size_t>(k)]);
            if (m >= 20 && previous[static_cast<std::size_t>(k)] > 1e-12) {
                EXPECT_LT(error, previous[static_cast<std::size_t>(k)] / 8.0);
            }
            previous[static_cast<std::size_t>(k)] = error;
        }
    }
    for (int k = 0; k < 3; ++k) EXPECT_LT(previous[static_cast<std::size_t>(k)], 1e-7);
}

double relative_difference(const SparseMatrix& a, const SparseMatrix& b) {
    return (Eigen::MatrixXd(a) - Eigen::MatrixXd(b)).norm() / Eigen::MatrixXd(a).norm();
}

// The plain beam written as one section and as two equal ones is the same model bit for bit; as one
// layer of a material equal to [material], the same to roundoff.
TEST(BeamSections, UniformBeamAsSectionsOrOneLayerIsThePlainBeam) {
    const Case plain = base_with("");
    const Case one = base_with("[[beam.sections]]\nfrom = 0\nto = 1\n");
    const Case two = base_with("[[beam.sections]]\nfrom = 0\nto = 0.5\n[[beam.sections]]\nfrom = 0.5\nto = 1\n"
                               "width = \"30 um\"\nthickness = \"2 um\"\n");
    const Case layer = base_with("[[materials]]\nname = \"nickel\"\nyoungs_modulus = \"200 GPa\"\n"
                                 "density = \"8900 kg/m^3\"\npoisson_ratio = 0.3\n"
                                 "[[beam.sections]]\nfrom = 0\nto = 1\nlayers = [{ material = \"nickel\", thickness = \"2 um\" }]\n");
    const System p = build_system(plain), s1 = build_system(one), s2 = build_system(two), s3 = build_system(layer);
    EXPECT_EQ(relative_difference(p.K, s1.K), 0.0);
    EXPECT_EQ(relative_difference(p.M, s1.M), 0.0);
    EXPECT_EQ(relative_difference(p.K, s2.K), 0.0);
    EXPECT_EQ(relative_difference(p.M, s2.M), 0.0);
    EXPECT_LT(relative_difference(p.K, s3.K), 1e-15);
    EXPECT_LT(relative_difference(p.M, s3.M), 1e-15);
    std::printf("one layer: K differs by %.2e, M by %.2e (relative)\n", relative_difference(p.K, s3.K),
                relative_difference(p.M, s3.M));
}

// The released tip of a cantilever of one section with the given layers: kappa = 2 v(l) / l^2 (the
// curl is a uniform curvature, which the cubic elements hold exactly).
double released_curvature(const std::string& materials, const std::string& layers) {
    const Case c = base_with(materials + "[[beam.sections]]\nfrom = 0\nto = 1\nlayers = [" + layers + "]\n");
    const BeamModel b = build_beam_model(c);
    const StaticState s = solve_static(b.K, b.forces, Eigen::VectorXd::Zero(b.K.rows()), {}, 200);
    const double l = c.beam.length;
    return 2.0 * s.q[b.watched.dof] / (l * l);
}

std::string material(const char* name, const char* e, const char* stress, const char* gradient = "0") {
    return std::string("[[materials]]\nname = \"") + name + "\"\nyoungs_modulus = \"" + e +
           "\"\ndensity = \"10000 kg/m^3\"\npoisson_ratio = 0.3\nresidual_stress = \"" + stress +
           "\"\nstress_gradient = " + gradient + "\n";
}

// Timoshenko's bimetal strip (J. Opt. Soc. Am. 11 (1925) 233, eq. 4): two layers of moduli E1, E2 and
// thicknesses t1 (bottom), t2 whose free strains differ by d = e1 - e2 curl by
// kappa = 6 d (1 + m)^2 / (h (3 (1 + m)^2 + (1 + m n)(m^2 + 1 / (m n)))), m = t1 / t2, n = E1 / E2,
// h = t1 + t2. A layer held at sigma has the free strain -sigma / E.
TEST(BeamSections, BilayerCurlsAsTimoshenkosBimetalStrip) {
    const double e1 = 160e9, e2 = 79e9, t1 = 0.5e-6, t2 = 1.5e-6, s1 = -200e6, s2 = 120e6;
    const double kappa = released_curvature(material("nitride", "160 GPa", "-200 MPa") + material("gold", "79 GPa", "120 MPa"),
                                            "{ material = \"nitride\", thickness = \"0.5 um\" }, "
                                            "{ material = \"gold\", thickness = \"1.5 um\" }");
    const double m = t1 / t2, n = e1 / e2, h = t1 + t2, d = -s1 / e1 + s2 / e2;
    const double timoshenko = 6.0 * d * (1 + m) * (1 + m) / (h * (3 * (1 + m) * (1 + m) + (1 + m * n) * (m * m + 1 / (m * n))));
    std::printf("bilayer: kappa %.12g 1/m, Timoshenko %.12g 1/m\n", kappa, timoshenko);
    EXPECT_GT(kappa, 0.0);  // the top pulls in tension, the bottom pushes: it curls up
    EXPECT_NEAR(kappa, timoshenko, 1e-9 * std::abs(timoshenko));
}

// One layer with a stress gradient Gamma curls by Gamma / E (tip lift Gamma l^2 / (2 E)); a uniform
// stress alone does not curl it.
TEST(BeamSections, LayerStressGradientCurlsByGammaOverE) {
    const double gamma = 1.5e13, e = 150e9;
    const double kappa = released_curvature(material("poly", "150 GPa", "50 MPa", "1.5e13"),
                                            "{ material = \"poly\", thickness = \"2 um\" }");
    EXPECT_NEAR(kappa, gamma / e, 1e-10 * gamma / e);
    EXPECT_EQ(released_curvature(material("poly", "150 GPa", "50 MPa"), "{ material = \"poly\", thickness = \"2 um\" }"), 0.0);
}

// An electrode under both sections of a stepped beam (30 um and 15 um wide): at rest its force is
// eps0 V^2 / (2 g^2) times the area it faces, section by section.
TEST(BeamSections, ElectrodeForceUsesTheWidthUnderIt) {
    const Case c = base_with(kStepped + "[[electrodes]]\nfrom = 0.2\nto = 0.9\ngap = \"2 um\"\nvoltage = \"10 V\"\n"
                                        "waveform = \"step\"\nt_on = \"0 us\"\n");
    const double total = test::rest_force(build_beam_model(c), "electrodes[0]", 1e-9);
    const double l = 100e-6, area = 30e-6 * 0.2 * l + 15e-6 * 0.5 * l;
    const double expected = -8.8541878128e-12 * 100.0 / (2.0 * 2e-6 * 2e-6) * area;
    EXPECT_NEAR(total, expected, 1e-12 * std::abs(expected));
}

std::string error_of(const std::string& extra) {
    return test::input_error_of([&] { base_with(extra); });
}

// Sections with a gap or an overlap, a layer naming no material, and a layered curl that closes a
// gap at rest: one line naming the file, the line and the key.
TEST(BeamSections, BadSectionsAreRefusedAtTheirLine) {
    EXPECT_EQ(error_of("[[beam.sections]]\nfrom = 0\nto = 0.4\n[[beam.sections]]\nfrom = 0.5\nto = 1\n"),
              "sections.toml:15: beam.sections[1].from: leaves a gap from x/l = 0.4 to 0.5 after beam.sections[0], "
              "which ends at x/l = 0.4; the sections must cover the beam from 0 to 1 in order, each from at the previous to");
    EXPECT_NE(error_of("[[beam.sections]]\nfrom = 0\nto = 0.6\n[[beam.sections]]\nfrom = 0.5\nto = 1\n")
                  .find("sections.toml:15: beam.sections[1].from: overlaps beam.sections[0]"),
              std::string::npos);
    EXPECT_NE(error_of("[[beam.sections]]\nfrom = 0\nto = 0.9\n").find("sections.toml:13: beam.sections[0].to: the last section must end at x/l = 1"),
              std::string::npos);
    EXPECT_EQ(error_of(material("gold", "79 GPa", "0 MPa") +
                       "[[beam.sections]]\nfrom = 0\nto = 1\nlayers = [{ material = \"gold\", thickness = \"1 um\" },\n"
                       "  { material = \"golf\", thickness = \"1 um\" }]\n"),
              "sections.toml:22: beam.sections[0].layers[1].material: no [[materials]] entry is named \"golf\" "
              "(materials: \"gold\")");
    const std::string closed = error_of(material("poly", "150 GPa", "0 MPa", "-3e13") +
                                        "[[beam.sections]]\nfrom = 0\nto = 1\nlayers = [{ material = \"poly\", thickness = \"2 um\" }]\n"
                                        "[[supports]]\nposition = 1\ngap = \"0.5 um\"\nstiffness = \"100 N/m\"\n");
    EXPECT_NE(closed.find("sections.toml:21: beam.sections[0].layers: the released shape closes the gap of supports[0] at x = 100 um "
                          "(x/l = 1): it moves 1 um toward a gap of 0.5 um, 0.5 um too far"),
              std::string::npos)
        << closed;
}

// A section's width and thickness are paths (sweeps, --set); the written case reads back the same.
TEST(BeamSections, SectionKeysArePathsAndTheWrittenCaseReadsBack) {
    Case c = base_with(material("gold", "79 GPa", "30 MPa") + kStepped);
    c.beam.sections[1].layers = {{"gold", 0.5e-6}};
    c.beam.sections[1].thickness.reset();
    set_case_text(c, "beam.sections[0].thickness", "1.5 um");
    EXPECT_EQ(c.beam.sections[0].thickness, 1.5e-6);
    EXPECT_EQ(resolve_case_path("beam.sections[1].width", c).text(), "beam.sections[1].width");
    EXPECT_EQ(case_path_column(resolve_case_path("beam.sections[1].width", c)), "beam.sections[1].width_m");
    const Case back = read_case_text(case_to_toml(c), "written.toml");
    ASSERT_EQ(back.beam.sections.size(), 2u);
    EXPECT_EQ(back.beam.sections[0].thickness, 1.5e-6);
    ASSERT_EQ(back.beam.sections[1].layers.size(), 1u);
    EXPECT_EQ(back.beam.sections[1].layers[0].material, "gold");
    EXPECT_EQ(back.beam.sections[1].layers[0].thickness, 0.5e-6);
    EXPECT_EQ(case_to_json(c)["beam"]["sections"][1]["layers"][0]["material"], "gold");
}

// A squeeze film under both sections (30 um and 15 um wide): at the gap at rest, a uniform unit
// velocity dissipates the film's c(w, g) = mu_eff w^3 / g^3 over each section's length.
TEST(BeamSections, SqueezeFilmUsesTheWidthOverIt) {
    const Case c = base_with(kStepped + "[air]\n[[films]]\nfrom = 0.2\nto = 0.9\ngap = \"2 um\"\n");
    const BeamModel b = build_beam_model(c);
    const ForceElement* film = nullptr;
    for (const auto& f : b.forces) {
        if (f->name() == "films[0]") film = f.get();
    }
    ASSERT_NE(film, nullptr);
    const std::vector<double> q(film->dofs().size(), 0.0);
    std::vector<double> v(film->dofs().size(), 0.0);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = b.is_v[static_cast<std::size_t>(film->dofs()[i])] ? 1.0 : 0.0;
    const double power = film->dissipated_power(ElementState{0.0, q.data(), v.data(), q.data()}, 0);
    const FilmGas gas{c.air->viscosity, c.air->lambda()};
    const double l = 100e-6;
    const double expected = film_coefficient(gas, 30e-6, 2e-6).c * 0.2 * l + film_coefficient(gas, 15e-6, 2e-6).c * 0.5 * l;
    EXPECT_NEAR(power, expected, 1e-12 * expected);
}

double ledger_total(const EnergyLedger& e) {
    return e.kinetic + e.strain + e.contact_spring + e.electrical + e.rayleigh_dissipated + e.contact_dissipated +
           e.film_dissipated - e.external_work;
}

// The paddle switch example (three sections of a titanium-gold stack, curled up by the layers'
// moment, a Hertz dimple) starts at rest in its released shape and closes; its energy ledger closes
// at every sample through the first 60 us (the first bounces), the curl's energy in the strain term.
TEST(BeamSections, SteppedLayeredCurledSwitchLedgerCloses) {
    Case c = read_case_file(test::source_path("examples/devices/ohmic_paddle_switch.toml"));
    c.solver.horizon = 60e-6;
    c.solver.rtol = 1e-10;
    c.solver.reduced_modes = 0;  // the full model: every DOF in the ledger
    const SimulationRun run = run_simulation(c);
    const TransientResult& r = run.result;
    ASSERT_FALSE(r.episodes.empty());
    ASSERT_FALSE(r.history.watched_v.empty());
    EXPECT_GT(r.history.watched_v.front(), 0.0);  // curled up at rest
    const double scale = std::abs(r.initial_energy.electrical) + std::abs(r.initial_energy.strain);
    const double start = ledger_total(r.initial_energy);
    double worst = 0.0;
    for (const EnergyLedger& e : r.history.energy) worst = std::max(worst, std::abs(ledger_total(e) - start) / scale);
    std::printf("paddle switch: tip at rest %.4g um, first contact %.4g us, %zu episodes, ledger drift at most %.2e\n",
                r.history.watched_v.front() * 1e6, r.episodes[0].t_on * 1e6, r.episodes.size(), worst);
    EXPECT_LT(worst, 1e-6);
}

// A stepped, layered cantilever released from a lift onto a linear stop: the exact event-driven
// solver and CVODE see the same model (first contact time and peak force agree to 1e-6).
TEST(BeamSections, ExactAndCvodeAgreeOnASteppedBeam) {
    const std::string text = material("gold", "79 GPa", "0 MPa") + kStepped +
                             "[[supports]]\nposition = 1\ngap = \"0.5 um\"\nstiffness = \"50 N/m\"\n"
                             "[initial]\nkind = \"displacement\"\ndisplacement = \"1 um\"\n"
                             "[damping]\nratios = [0.02, 0.02]\n[solver]\nhorizon = \"10 us\"\nrtol = 1e-10\n";
    Case exact = base_with(text);
    exact.beam.sections[1].thickness.reset();
    exact.beam.sections[1].layers = {{"gold", 1.2e-6}};
    Case cvode = exact;
    exact.solver.method = SolverSettings::Method::exact;
    cvode.solver.method = SolverSettings::Method::cvode;
    const TransientResult a = run_simulation(exact).result, b = run_simulation(cvode).result;
    ASSERT_FALSE(a.episodes.empty());
    ASSERT_FALSE(b.episodes.empty());
    std::printf("stepped beam: first contact %.12g us exact, %.12g us CVODE; peak force %.8g N, %.8g N\n",
                a.episodes[0].t_on * 1e6, b.episodes[0].t_on * 1e6, a.episodes[0].peak_force, b.episodes[0].peak_force);
    EXPECT_NEAR(a.episodes[0].t_on, b.episodes[0].t_on, 1e-6 * a.episodes[0].t_on);
    EXPECT_NEAR(a.episodes[0].peak_force, b.episodes[0].peak_force, 1e-5 * a.episodes[0].peak_force);
}

}  // namespace sections_test
}  // namespace vi
