// The squeeze film (forces/squeeze_film.hpp) against closed forms and published formulas
// (docs/squeeze-film.md, docs/validation.md): the rigid strip's damping, the rarefaction factor, the
// finite plate's factor, the quality factor of the paper's cantilever against a ring-down, and the
// energy ledger of a transient in air.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "case_text_fixture.hpp"
#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "forces/squeeze_film.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "report/transient_output.hpp"
#include "study/air/air_q.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

// The base case (100 um x 30 um x 2 um, 20 elements) with a film over x/l = 0.13 .. 0.87 (ends
// inside elements) 2 um below, in air with a given mean free path.
BuiltProblem strip_problem(const std::string& mean_free_path) {
    const std::string text = test::kBaseCase + "[air]\nmean_free_path = \"" + mean_free_path +
                             "\"\n[[films]]\nfrom = 0.13\nto = 0.87\ngap = \"2 um\"\n";
    return build_transient_problem(read_case_text(text, "strip.toml"));
}

const SqueezeFilm& film_of(const BuiltProblem& b) {
    for (const ForceElementPtr& e : b.problem.forces) {
        if (const auto* f = dynamic_cast<const SqueezeFilm*>(e.get())) return *f;
    }
    throw std::logic_error("no film");
}

// Whether element DOF i is a transverse displacement (not a rotation).
bool is_v(const BuiltProblem& b, int dof) {
    return b.model.system.free_dofs[static_cast<std::size_t>(b.model.system.bending[static_cast<std::size_t>(dof)])] % 3 == 1;
}

// A rigid strip of width w and length L at gap g moving at dg/dt has c = mu_eff w^3 L / g^3 in the
// narrow-plate limit (Reynolds across the width, p = 0 at its edges). A uniform translation of the
// beam (every v DOF moved by d at speed U, rotations 0) is that strip: the film's total force must be
// -c U to quadrature roundoff, with g = 2 um + d (film below) and mu_eff at Kn = lambda / g.
TEST(SqueezeFilm, RigidStripMatchesTheNarrowPlateClosedForm) {
    const BuiltProblem b = strip_problem("68 nm");
    const SqueezeFilm& f = film_of(b);
    const std::size_t n = f.dofs().size();
    for (const double d : {0.0, -0.5e-6, 0.3e-6}) {
        for (const double U : {-0.2, 0.05}) {
            std::vector<double> q(n, 0.0), v(n, 0.0), force(n, 0.0);
            for (std::size_t i = 0; i < n; ++i) {
                if (is_v(b, f.dofs()[i])) {
                    q[i] = d;
                    v[i] = U;
                }
            }
            const ElementState s{0.0, q.data(), v.data(), nullptr};
            f.add_force(s, 0, force.data());
            double total = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                if (is_v(b, f.dofs()[i])) total += force[i];
            }
            const double mu = 1.85e-5, w = 30e-6, L = 0.74 * 100e-6, g = 2e-6 + d;
            const double mu_eff = mu / (1.0 + 9.638 * std::pow(68e-9 / g, 1.159));
            const double c = mu_eff * w * w * w * L / (g * g * g);
            EXPECT_NEAR(total, -c * U, 1e-12 * c * std::abs(U)) << "d = " << d << ", U = " << U;
            EXPECT_NEAR(f.dissipated_power(s, 0), c * U * U, 1e-12 * c * U * U);
        }
    }
}

// Veijola's rarefaction factor at Kn = 0.01, 0.1, 1, 10, as the film applies it (its damping over
// the continuum value mu w^3 / g^3 at one gap), against the formula; then against two other
// published slip models at small Kn, where all are 1 + O(Kn): Burgdorfer's first-order slip 1 + 6 Kn
// (A. Burgdorfer, J. Basic Eng. 81 (1959) 94-100) and Hsia and Domoto's second-order 1 + 6 Kn +
// 6 Kn^2 (J. Lubrication Technol. 105 (1983) 120-130). The differences measured are printed and
// quoted in docs/validation.md.
TEST(SqueezeFilm, RarefactionFactorIsVeijolasAndAgreesWithSlipModelsAtSmallKnudsen) {
    const double mu = 1.85e-5, w = 30e-6, g = 1e-6;
    for (const double kn : {0.01, 0.1, 1.0, 10.0}) {
        const FilmCoefficient k = film_coefficient(FilmGas{mu, kn * g}, w, g);
        const double factor = (mu * w * w * w / (g * g * g)) / k.c;
        EXPECT_NEAR(factor, 1.0 + 9.638 * std::pow(kn, 1.159), 1e-13 * factor) << "Kn = " << kn;
        std::printf("Kn %-5g Veijola %.5f  Burgdorfer %.5f (%+.2f%%)  Hsia-Domoto %.5f (%+.2f%%)\n", kn, factor,
                    1.0 + 6.0 * kn, 100.0 * ((1.0 + 6.0 * kn) / factor - 1.0), 1.0 + 6.0 * kn + 6.0 * kn * kn,
                    100.0 * ((1.0 + 6.0 * kn + 6.0 * kn * kn) / factor - 1.0));
    }
    // O(Kn) agreement: |Q_V - Q_B| <= 6 Kn (each within its first-order term of 1).
    for (const double kn : {1e-4, 1e-3, 1e-2}) {
        EXPECT_LE(std::abs(veijola_factor(kn) - (1.0 + 6.0 * kn)), 6.0 * kn) << kn;
        EXPECT_LE(std::abs(veijola_factor(kn) - (1.0 + 6.0 * kn + 6.0 * kn * kn)), 6.0 * kn) << kn;
    }
    // At Kn = 0.01 the three agree within 1.5 % (measured: 1.3 % and 1.4 %).
    EXPECT_NEAR(veijola_factor(0.01), 1.06, 0.015 * 1.06);
}

// The film's dc/dg is the derivative of c(g) (what the tangent's dfdq uses), checked by central
// differences across the slip regimes.
TEST(SqueezeFilm, CoefficientDerivativeMatchesDifferences) {
    for (const double lambda : {1e-9, 68e-9, 5e-6}) {
        const FilmGas gas{1.85e-5, lambda};
        for (const double g : {0.2e-6, 1e-6, 3e-6}) {
            const double h = 1e-6 * g;
            const double fd = (film_coefficient(gas, 30e-6, g + h).c - film_coefficient(gas, 30e-6, g - h).c) / (2 * h);
            const double an = film_coefficient(gas, 30e-6, g).dc;
            EXPECT_NEAR(an, fd, 1e-8 * std::abs(fd)) << "lambda " << lambda << " g " << g;
        }
    }
}

// The finite rectangular plate (Blech 1983; Bao 2005): beta -> 1 for a long strip, 0.4217 for a
// square plate (the published square-plate coefficient c = 0.42 mu a^4 / g^3), and the linear form
// 1 - 0.6 w/L that the handbooks quote is within 1 % of the series up to the paper's beam's w/L =
// 30/117 (measured: 0.92 % there, 1.12 % at w/L = 0.3).
TEST(SqueezeFilm, FinitePlateFactorMatchesPublishedValues) {
    EXPECT_NEAR(rectangular_plate_factor(1e-6), 1.0, 1e-6);
    EXPECT_NEAR(rectangular_plate_factor(1.0), 0.4217, 5e-5);
    // Small w/L: the slope is -(192/pi^5) sum 1/n^5 (odd n) = -0.6302.
    EXPECT_NEAR((1.0 - rectangular_plate_factor(1e-3)) / 1e-3, 0.6302, 1e-4);
    for (const double eta : {0.05, 0.1, 0.2, 30.0 / 117.0}) {
        const double beta = rectangular_plate_factor(eta);
        std::printf("w/L %.4f  beta %.5f  1 - 0.6 w/L %.5f (%+.2f%%)\n", eta, beta, 1.0 - 0.6 * eta,
                    100.0 * ((1.0 - 0.6 * eta) / beta - 1.0));
        EXPECT_NEAR(1.0 - 0.6 * eta, beta, 0.01 * beta) << eta;
    }
}

// The film must never be evaluated with the beam at the surface: at 1e-3 of its gap it throws, with
// its name, so that the solver reports it.
TEST(SqueezeFilm, RefusesAClosedGap) {
    const BuiltProblem b = strip_problem("68 nm");
    const SqueezeFilm& f = film_of(b);
    const std::size_t n = f.dofs().size();
    std::vector<double> q(n, 0.0), v(n, 0.1), force(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        if (is_v(b, f.dofs()[i])) q[i] = -2e-6 * (1.0 - 1e-4);  // down to 0.2 nm of the surface
    }
    try {
        f.add_force(ElementState{0.0, q.data(), v.data(), nullptr}, 0, force.data());
        FAIL() << "no error";
    } catch (const std::domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("films[0]"), std::string::npos) << e.what();
    }
}

// A film over an electrode's dielectric layer ends where the layer (a contact) begins: below
// kFilmEndGap of its gap, and pressed into the layer, its law is held at that gap instead of failing.
TEST(SqueezeFilm, EndsOnADielectricLayer) {
    const std::string text = test::kBaseCase +
                             "[air]\n[[electrodes]]\nfrom = 0.1\nto = 1.0\ngap = \"2 um\"\ndielectric_thickness = "
                             "\"0.2 um\"\ndielectric_permittivity = 7.5\nvoltage = \"60 V\"\nwaveform = \"step\"\n";
    const BuiltProblem b = build_transient_problem(read_case_text(text, "layer.toml"));
    const SqueezeFilm& f = film_of(b);
    EXPECT_EQ(f.name(), "electrodes[0].film");
    EXPECT_TRUE(f.geometry().ends_on_contact);
    const std::size_t n = f.dofs().size();
    const double air = 1.8e-6;
    const auto rigid = [&](double d) {  // every v DOF moved by d (down: negative), rotations 0
        std::vector<double> q(n, 0.0);
        for (std::size_t i = 0; i < n; ++i) q[i] = is_v(b, f.dofs()[i]) ? d : 0.0;
        return q;
    };
    std::vector<double> v(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) v[i] = is_v(b, f.dofs()[i]) ? -0.1 : 0.0;
    const auto power = [&](double d) {
        const std::vector<double> q = rigid(d);
        return f.dissipated_power(ElementState{0.0, q.data(), v.data(), nullptr}, 0);
    };
    const double at_end = power(-air * (1.0 - kFilmEndGap));
    EXPECT_GT(at_end, 0.0);
    // Closer, touching and pressed 1 nm into the layer: the same film as at its end.
    for (double d : {-air * (1.0 - 1e-5), -air, -air - 1e-9}) EXPECT_NEAR(power(d), at_end, 1e-9 * at_end) << d;
    // Above its end the film is the gap law's, which grows as the gap closes.
    EXPECT_LT(power(-air * (1.0 - 10.0 * kFilmEndGap)), at_end);
}

// The capacitive switch example in air: the stiction check, which lays the beam on its layer and lets
// it settle, says it sticks (it failed at the film before), and a 60 V step lands it on the layer
// later than in vacuum (the film slows the approach).
TEST(SqueezeFilm, TheCapacitiveSwitchLandsAndSticksInAir) {
    const std::string file = test::source_path("examples/switch/capacitive_stiction.toml");
    const std::string dir = test::make_temp_dir();
    std::string text = test::read_text(file);
    const auto at = text.find("waveform = \"pulse\"");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, std::string("waveform = \"pulse\"").size(), "waveform = \"step\"");
    for (const char* key : {"\nrise = \"0.5 us\"", "\nhold = \"3 us\"", "\nfall = \"0.5 us\""}) {
        ASSERT_NE(text.find(key), std::string::npos) << key;
        text.erase(text.find(key), std::string(key).size());
    }
    test::write_text(dir + "/vacuum.toml", text);
    test::write_text(dir + "/air.toml", text + "\n[air]\n");
    const auto st = test::run_vibroimpact({"stiction", dir + "/air.toml", "--json"}, 60.0);
    ASSERT_EQ(st.exit_code, 0) << st.err;
    const nlohmann::json layer = nlohmann::json::parse(st.out)["layers"][0];
    EXPECT_EQ(layer["verdict"], "sticks");
    EXPECT_TRUE(layer["settled"]["stuck"].get<bool>());
    const auto closing = [&](const std::string& name) {
        const auto r = test::run_vibroimpact({"simulate", dir + "/" + name, "--json"}, 60.0);
        EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
        if (r.exit_code != 0) return 0.0;
        const nlohmann::json sw = nlohmann::json::parse(r.out)["switching"];
        EXPECT_EQ(sw["state"], "closed") << name;
        return sw["closing_time_s"].get<double>();
    };
    const double vacuum = closing("vacuum.toml"), air = closing("air.toml");
    std::printf("capacitive switch, 60 V step: lands at %.4g us in vacuum, %.4g us in air\n", vacuum * 1e6, air * 1e6);
    EXPECT_GT(air, vacuum);
    EXPECT_LT(air, 20e-6);
}

// Q of the paper's cantilever (nickel 117 x 30 x 2 um) with a film under the whole beam at a 1 um
// gap. The film is uniform along the beam, so its damping matrix is (c / rho A) M to quadrature
// roundoff and Q_modal = omega1 rho A / c exactly (c = mu_eff w^3 / g^3); the ring-down transient
// (tip amplitude 1e-3 g, where the film's nonlinearity changes the cycle-averaged damping by
// O((a/g)^2) = 1e-6) must give the same Q. Tolerance 1e-4: the parabolic location of sampled maxima
// (200 samples per period) is exact to about 1e-7 of the amplitude, which over the decay of 10
// periods at Q = 1000 (3 %) is 3e-6 of the decay rate; CVODE's rtol is 1e-10; 1e-4 leaves room
// for the second mode the first one's nonlinearity feeds.
TEST(SqueezeFilm, QualityFactorOfThePaperCantileverFromARingDown) {
    const Case base = read_case_file(test::source_path("examples/paper/cantilever.toml"));
    const Case c = air_q_case(base, 1e-6);
    const double rhoA = 8902.0 * 30e-6 * 2e-6, w = 30e-6, g = 1e-6;
    const double w1 = build_beam_model(c).omega1;
    for (const double p : {101325.0, 1e4, 1e3, 100.0}) {
        const AirQPoint x = air_q_point(c, p);
        const double kn = 68e-9 * 101325.0 / p / g;
        const double c_line = 1.85e-5 / (1.0 + 9.638 * std::pow(kn, 1.159)) * w * w * w / (g * g * g);
        EXPECT_NEAR(x.q_modal, w1 * rhoA / c_line, 1e-10 * x.q_modal) << p << " Pa";
        ASSERT_TRUE(x.q_ringdown.has_value()) << p << " Pa";
        std::printf("p %6g Pa  Kn %8.4g  sigma %8.3g  Q_modal %10.5f  Q_ringdown %10.5f (%+.2e)  maxima %d\n", p,
                    x.knudsen, x.squeeze_number, x.q_modal, *x.q_ringdown, *x.q_ringdown / x.q_modal - 1.0, x.maxima);
        EXPECT_NEAR(*x.q_ringdown, x.q_modal, 1e-4 * x.q_modal) << p << " Pa";
    }
}

// The ledger closes with the film: kinetic + strain - external work + the film's dissipation (its
// own term, film_dissipated) + Rayleigh's is constant through a release in air at 1 atm
// (Q about 7 from the film, 100 from the material; the Rayleigh damping also keeps CVODE from
// resolving the undamped high modes the static step excites).
TEST(SqueezeFilm, EnergyLedgerClosesInAir) {
    const std::string text = test::kBaseCase +
                             "[damping]\nratios = [0.005, 0.005]\nmodes = [1, 2]\n"
                             "[air]\n[[films]]\nfrom = 0.0\nto = 1.0\ngap = \"2 um\"\n"
                             "[initial]\nkind = \"displacement\"\ndisplacement = \"0.5 um\"\n"
                             "[solver]\nmethod = \"cvode\"\nhorizon = \"20 us\"\n";
    BuiltProblem b = build_transient_problem(read_case_text(text, "ledger.toml"));
    const TransientResult r = solve_cvode(b.problem);
    const auto total = [](const EnergyLedger& e) {
        return e.kinetic + e.strain + e.contact_spring + e.electrical + e.rayleigh_dissipated + e.contact_dissipated +
               e.film_dissipated - e.external_work;
    };
    const double e0 = total(r.initial_energy);
    ASSERT_GT(e0, 0.0);
    EXPECT_GT(r.final_energy.film_dissipated, 0.5 * e0);  // the film took most of it
    EXPECT_EQ(r.final_energy.contact_dissipated, 0.0);    // and there is no contact to book it to
    EXPECT_LT(std::abs(total(r.final_energy) - e0), 1e-7 * e0);
    for (const EnergyLedger& e : r.history.energy) EXPECT_LT(std::abs(total(e) - e0), 1e-7 * e0);
}

// The film's term is written where a model has a film, and only there: summary.json's energy and a
// column of history.csv.
TEST(SqueezeFilm, LedgerFilesCarryTheFilmTermOnlyWithAFilm) {
    const std::string vacuum = test::kBaseCase + "[damping]\nratios = [0.005, 0.005]\nmodes = [1, 2]\n"
                                                 "[initial]\nkind = \"displacement\"\ndisplacement = \"0.5 um\"\n"
                                                 "[solver]\nmethod = \"cvode\"\nhorizon = \"2 us\"\n";
    const std::string air = vacuum + "[air]\n[[films]]\nfrom = 0.0\nto = 1.0\ngap = \"2 um\"\n";
    for (const bool with_film : {false, true}) {
        const Case c = read_case_text(with_film ? air : vacuum, "ledger.toml");
        const SimulationRun run = run_simulation(c);
        const OutputFiles files = transient_files(c, run.built, run.result, run.summary);
        const nlohmann::json j = nlohmann::json::parse(files.at("summary.json"));
        EXPECT_EQ(j["energy"]["final"].contains("film_dissipated_j"), with_film);
        const std::string header = files.at("history.csv").substr(0, files.at("history.csv").find('\n'));
        EXPECT_EQ(header.find("film_dissipated_j") != std::string::npos, with_film) << header;
        if (with_film) {
            EXPECT_GT(j["energy"]["final"]["film_dissipated_j"].get<double>(), 0.0);
        }
    }
}

}  // namespace
}  // namespace vi
