// Adhesion at a support (issue 14, items 2-5; docs/adhesion.md): the pull-off forces of the DMT and
// JKR models, the release condition of a one-degree-of-freedom adhesive contact (static and
// transient), the energy ledger through adhesive impacts, the stuck cantilever's detached length,
// and the case keys with their refusals.

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>

#include <unistd.h>

#include "case_text_fixture.hpp"
#include "dynamics/cvode/cvode_solver.hpp"
#include "statics/static_solution.hpp"
#include "dynamics/transient_problem.hpp"
#include "forces/adhesive_contact.hpp"
#include "forces/point_load_element.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"
#include "study/stiction/stiction.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

// A mass m on a spring k held on an adhesive contact (Kc, F_po, range) at q = 0, pulled up by a
// load P(t) = P g(t). In contact the spring and the contact share the load: the contact pulls with
// Kc P / (k + Kc), so it lets go (F < -F_po) exactly above P* = F_po (1 + k / Kc); there the spring
// itself pulls with k (P/k - q) = F_po at the contact's stretch q = F_po / Kc.
struct Sdof {
    double m = 1e-9, k = 10.0, kc = 1000.0, fpo = 1e-6, range = 2e-9;
    [[nodiscard]] double threshold() const { return fpo * (1.0 + k / kc); }
    [[nodiscard]] double omega_closed() const { return std::sqrt((k + kc) / m); }
};

Eigen::SparseMatrix<double> one_by_one(double v) {
    Eigen::SparseMatrix<double> a(1, 1);
    a.insert(0, 0) = v;
    return a;
}

// The load ramps over `ramp` then holds; mass damping alpha gives the closed system a ratio 1.5, so
// the contact's tension rises monotonically to its static value (no overshoot past the threshold).
TransientProblem sdof_pull(const Sdof& s, double load, double ramp, double horizon) {
    TransientProblem p;
    p.M = one_by_one(s.m);
    p.K = one_by_one(s.k);
    p.alpha = 2.0 * 1.5 * s.omega_closed();
    p.forces.push_back(std::make_shared<AdhesiveContact>("supports[0]", 0, 1.0, 0.0, s.kc, 0.0, 0.0, s.fpo, s.range, "DMT"));
    TimeFunction g;
    g.kind = TimeFunction::Kind::table;
    g.times = {0.0, ramp};
    g.values = {0.0, 1.0};
    p.forces.push_back(std::make_shared<PointLoadElement>("loads[0]", std::vector<int>{0}, std::vector<double>{1.0}, load, g, 0.0));
    p.q0 = Eigen::VectorXd::Zero(1);
    p.v0 = Eigen::VectorXd::Zero(1);
    p.tip_dof = 0;
    p.t_end = horizon;
    p.output_step = horizon / 200.0;
    return p;
}

bool released(const TransientResult& r) { return !r.episodes.empty() && !r.episodes.back().closed_at_end; }

TEST(Adhesion, PullOffForcesOfDmtAndJkr) {
    Support s;
    s.work_of_adhesion = 0.1;
    s.contact_radius = 2e-6;
    EXPECT_EQ(s.pull_off_force(), 0.0);
    s.adhesion = Adhesion::dmt;
    EXPECT_DOUBLE_EQ(s.pull_off_force(), 2.0 * std::numbers::pi * 2e-6 * 0.1);
    s.adhesion = Adhesion::jkr;
    EXPECT_DOUBLE_EQ(s.pull_off_force(), 1.5 * std::numbers::pi * 2e-6 * 0.1);
}

// Static: from the closed contact, the active-set solution stays closed up to P* and not above it.
// Above P* the open equilibrium lies beyond the cohesive zone, whose negative stiffness F_po / range
// (500 N/m) exceeds k: Newton from the contact walks back into it and the iteration ends at its bound
// (WorkLimitReached), which counts as "does not hold" (docs/adhesion.md §6). Bisection on P (40
// halvings of [0.5, 2] P*) brackets P* to within 1e-6 relative.
TEST(Adhesion, SdofStaticReleaseThresholdIsThePullOffForce) {
    const Sdof s;
    ForceSet contact{std::make_shared<AdhesiveContact>("supports[0]", 0, 1.0, 0.0, s.kc, 0.0, 0.0, s.fpo, s.range, "DMT")};
    const auto holds = [&](double load) {
        try {
            const StaticState st = solve_static(one_by_one(s.k), contact, Eigen::VectorXd::Constant(1, load), {1}, 50);
            return st.modes[0] == 1;
        } catch (const WorkLimitReached&) {
            return false;
        }
    };
    double lo = 0.5 * s.threshold(), hi = 2.0 * s.threshold();
    ASSERT_TRUE(holds(lo));
    ASSERT_FALSE(holds(hi));
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (holds(mid) ? lo : hi) = mid;
    }
    EXPECT_LT(std::abs(lo / s.threshold() - 1.0), 1e-6);
    EXPECT_LT(std::abs(hi / s.threshold() - 1.0), 1e-6);
    std::printf("static release threshold: bracket [%.9g, %.9g] x P*\n", lo / s.threshold(), hi / s.threshold());
}

// Transient: a ramp to 0.98 P* leaves the contact closed, pulling with Kc P / (k + Kc); a ramp to
// 1.02 P* releases it, and the mass leaves the adhesion range.
TEST(Adhesion, SdofTransientSticksBelowAndReleasesAbove) {
    const Sdof s;
    const double period = 2.0 * std::numbers::pi / s.omega_closed();
    const double ramp = 20.0 * period, horizon = 200.0 * period;
    const double p_stick = 0.98 * s.threshold();
    const TransientResult stuck = solve_cvode(sdof_pull(s, p_stick, ramp, horizon));
    ASSERT_EQ(stuck.episodes.size(), 1u);
    EXPECT_TRUE(stuck.episodes.front().closed_at_end);
    EXPECT_NEAR(stuck.history.contact_force[0].back(), -s.kc * p_stick / (s.k + s.kc), 1e-6 * s.fpo);

    const TransientResult free = solve_cvode(sdof_pull(s, 1.02 * s.threshold(), ramp, horizon));
    ASSERT_TRUE(released(free));
    EXPECT_GT(free.history.tip_v.back(), s.fpo / s.kc + s.range);  // beyond d_end: no more attraction
}

// Bisection on the transient's verdict (ramp, hold to 200 periods: the tension's approach to its
// static value is then e^-70 away) finds P* to 1e-6 relative.
TEST(Adhesion, SdofTransientReleaseThresholdByBisection) {
    const Sdof s;
    const double period = 2.0 * std::numbers::pi / s.omega_closed();
    double lo = 0.9 * s.threshold(), hi = 1.1 * s.threshold();
    for (int i = 0; i < 20; ++i) {
        const double mid = 0.5 * (lo + hi);
        (released(solve_cvode(sdof_pull(s, mid, 20.0 * period, 200.0 * period))) ? hi : lo) = mid;
    }
    EXPECT_LT(std::abs(lo / s.threshold() - 1.0), 1e-6) << "lo " << lo << " P* " << s.threshold();
    EXPECT_LT(std::abs(hi / s.threshold() - 1.0), 1e-6);
    std::printf("transient release threshold: bracket [%.9g, %.9g] x P*\n", lo / s.threshold(), hi / s.threshold());
}

// Undamped, the mass thrown at the adhesive contact (snapped in over the range, pulled back out past
// the pull-off force) keeps kinetic + spring + contact energy, the adhesion's potential included.
TEST(Adhesion, EnergyLedgerClosesThroughAdhesiveImpacts) {
    const Sdof s;
    TransientProblem p;
    p.M = one_by_one(s.m);
    p.K = one_by_one(s.k);
    const double gap = 50e-9;
    p.forces.push_back(std::make_shared<AdhesiveContact>("supports[0]", 0, 1.0, -gap, s.kc, 0.0, 0.0, s.fpo, s.range, "DMT"));
    p.q0 = Eigen::VectorXd::Zero(1);
    p.v0 = Eigen::VectorXd::Constant(1, -0.05);
    p.tip_dof = 0;
    const double period = 2.0 * std::numbers::pi * std::sqrt(s.m / s.k);
    p.t_end = 5.0 * period;
    p.output_step = p.t_end / 2000.0;
    CvodeOptions o;
    o.rtol = 1e-11;
    const TransientResult r = solve_cvode(p, o);
    ASSERT_GE(r.episodes.size(), 4u);  // it hits and leaves again every period
    const auto total = [](const EnergyLedger& e) { return e.kinetic + e.strain + e.contact_spring; };
    const double e0 = total(r.initial_energy);
    double worst = 0.0;
    for (const EnergyLedger& e : r.history.energy) {
        worst = std::max(worst, std::abs(total(e) + e.contact_dissipated - e0) / e0);
    }
    EXPECT_LT(worst, 1e-7);
    EXPECT_LT(std::abs(r.final_energy.contact_dissipated), 1e-9 * e0);  // no energy jumps at the switches
    std::printf("adhesive impacts: %zu episodes, worst ledger error %.3g of the initial energy\n", r.episodes.size(), worst);
}

// The S-shaped stuck cantilever: the FE energy balance agrees with l_d = (3 E t^3 h^2 / (2 gamma))^(1/4)
// on any mesh, because the clamped-guided span's deflection is a cubic, which the Hermite elements
// hold exactly: what is left is the bisection's error and rounding (measured below 1e-10).
TEST(Adhesion, DetachedLengthOfTheStuckCantileverMatchesTheClosedForm) {
    Case c = read_case_text(test::kBaseCase, "base.toml");
    const double E = c.material.effective_modulus(), t = c.beam.thickness, h = 1.5e-6, gamma = 0.01;
    const double closed = detached_length_closed_form(E, t, h, gamma);
    EXPECT_NEAR(closed, std::pow(1.5 * 200e9 * 8e-18 * 2.25e-12 / 0.01, 0.25), 1e-12 * closed);
    for (int m : {1, 2, 8, 50}) {
        const double fe = detached_length_fe(c, h, gamma, m);
        EXPECT_LT(std::abs(fe / closed - 1.0), 1e-10) << m << " elements: " << fe;
        std::printf("detached length, %d elements: FE/closed - 1 = %.3g\n", m, fe / closed - 1.0);
    }
}

// The stiction check of a cantilever with an adhesive stop under its free end: the restoring force
// is the tip stiffness 3 E I / l^3 times the gap.
TEST(Adhesion, StictionCheckOfATipContact) {
    const std::string text = test::kBaseCase +
                             "[[supports]]\nposition = 1.0\ngap = \"1 um\"\nstiffness = \"1000 N/m\"\n"
                             "adhesion = \"dmt\"\nwork_of_adhesion = \"0.1 J/m^2\"\ncontact_radius = \"1 um\"\n";
    const Case c = read_case_text(text, "tip.toml");
    const StictionResult r = stiction_check(c);
    ASSERT_EQ(r.supports.size(), 1u);
    const double EI = 200e9 * 30e-6 * 8e-18 / 12.0, l = 100e-6;
    const double restoring = 3.0 * EI / (l * l * l) * 1e-6;
    EXPECT_NEAR(r.supports[0].restoring_force, restoring, 1e-9 * restoring);
    const double fpo = 2.0 * std::numbers::pi * 1e-6 * 0.1;
    EXPECT_DOUBLE_EQ(r.supports[0].pull_off_force, fpo);
    EXPECT_EQ(r.supports[0].sticks, restoring < fpo);
    ASSERT_TRUE(r.supports[0].critical_work_of_adhesion);
    EXPECT_NEAR(*r.supports[0].critical_work_of_adhesion, r.supports[0].restoring_force / (2.0 * std::numbers::pi * 1e-6),
                1e-12);
    ASSERT_EQ(r.detached.size(), 1u);
    EXPECT_NEAR(r.detached[0].closed_form, detached_length_closed_form(200e9, 2e-6, 1e-6, 0.1), 1e-15);
}

// Bad adhesion input: one line naming file:line:key, as every reading error.
void expect_error(const std::string& text, const std::string& prefix) {
    try {
        (void)read_case_text(text, "bad.toml");
        ADD_FAILURE() << "accepted:\n" << text;
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.substr(0, prefix.size()), prefix) << "full message: " << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

// Lines 11-14 of the support; the adhesion keys from line 15 on.
std::string adhesive(const std::string& keys) {
    return test::kBaseCase + "[[supports]]\nposition = 1.0\ngap = \"1 um\"\nstiffness = \"1000 N/m\"\n" + keys;
}

TEST(Adhesion, CaseKeysAndRefusals) {
    const Case c = read_case_text(adhesive("adhesion = \"jkr\"\nwork_of_adhesion = \"50 mJ/m^2\"\n"
                                           "contact_radius = \"2 um\"\nadhesion_range = \"5 nm\"\n"),
                                  "ok.toml");
    EXPECT_EQ(c.supports[0].adhesion, Adhesion::jkr);
    EXPECT_DOUBLE_EQ(c.supports[0].work_of_adhesion, 0.05);
    EXPECT_DOUBLE_EQ(c.supports[0].contact_radius, 2e-6);
    EXPECT_DOUBLE_EQ(c.supports[0].adhesion_range, 5e-9);
    EXPECT_DOUBLE_EQ(read_case_text(adhesive("adhesion = \"dmt\"\nwork_of_adhesion = 0.1\ncontact_radius = \"1 um\"\n"),
                                    "ok.toml").supports[0].adhesion_range, kDefaultAdhesionRange);

    expect_error(adhesive("adhesion = \"dmt\"\nwork_of_adhesion = 0\ncontact_radius = \"1 um\"\n"),
                 "bad.toml:16: supports[0].work_of_adhesion: must be positive");
    expect_error(adhesive("adhesion = \"dmt\"\nwork_of_adhesion = -0.1\ncontact_radius = \"1 um\"\n"),
                 "bad.toml:16: supports[0].work_of_adhesion: must be positive");
    expect_error(adhesive("adhesion = \"dmt\"\nwork_of_adhesion = 0.1\ncontact_radius = \"-1 um\"\n"),
                 "bad.toml:17: supports[0].contact_radius: must be positive");
    expect_error(adhesive("adhesion = \"jkr\"\nwork_of_adhesion = 0.1\ncontact_radius = \"1 um\"\nadhesion_range = 0\n"),
                 "bad.toml:18: supports[0].adhesion_range: must be positive");
    // A missing key is placed at its table's header, as every missing key.
    expect_error(adhesive("adhesion = \"dmt\"\ncontact_radius = \"1 um\"\n"),
                 "bad.toml:11: supports[0].work_of_adhesion: missing required key");
    expect_error(adhesive("work_of_adhesion = 0.1\n"),
                 "bad.toml:15: supports[0].work_of_adhesion: only with supports[0].adhesion = \"dmt\" or \"jkr\"");
    expect_error(adhesive("adhesion = \"none\"\ncontact_radius = \"1 um\"\n"),
                 "bad.toml:16: supports[0].contact_radius: only with supports[0].adhesion = \"dmt\" or \"jkr\"");
    expect_error(adhesive("adhesion = \"glue\"\n"), "bad.toml:15: supports[0].adhesion:");
    expect_error(adhesive("adhesion = \"dmt\"\nwork_of_adhesion = \"0.1 N\"\ncontact_radius = \"1 um\"\n"),
                 "bad.toml:16: supports[0].work_of_adhesion:");
    expect_error(adhesive("adhesion = \"dmt\"\nwork_of_adhesion = 0.1\ncontact_radius = \"1 um\"\n"
                          "[solver]\nmethod = \"exact\"\n"),
                 "bad.toml:19: solver.method: \"exact\" cannot take the adhesive contact of supports[0].adhesion");
}

// The command line: a bad adhesion value exits 2 with one line naming file:line:key and writes
// nothing; `stiction` on a case without adhesion exits 2 naming the supports.
TEST(Adhesion, CommandsRefuseBadAdhesionWithExitTwo) {
    namespace fs = std::filesystem;
    const std::string dir = (fs::temp_directory_path() / ("vi_adhesion_" + std::to_string(::getpid()))).string();
    fs::create_directories(dir);
    test::write_text(dir + "/bad.toml", adhesive("adhesion = \"dmt\"\nwork_of_adhesion = 0\ncontact_radius = \"1 um\"\n"
                                                  "[solver]\nhorizon = \"10 us\"\n"));
    const auto sim = test::run_vibroimpact({"simulate", dir + "/bad.toml", "--out", dir + "/out"});
    EXPECT_EQ(sim.exit_code, 2);
    EXPECT_NE(sim.err.find(dir + "/bad.toml:16: supports[0].work_of_adhesion: must be positive"), std::string::npos)
        << sim.err;
    EXPECT_EQ(std::count(sim.err.begin(), sim.err.end(), '\n'), 1) << sim.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
    test::write_text(dir + "/plain.toml", test::kBaseCase + "[[supports]]\nposition = 1.0\nstiffness = \"1000 N/m\"\n");
    const auto st = test::run_vibroimpact({"stiction", dir + "/plain.toml"});
    EXPECT_EQ(st.exit_code, 2);
    EXPECT_NE(st.err.find("plain.toml:11: supports: no support has adhesion"), std::string::npos) << st.err;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
