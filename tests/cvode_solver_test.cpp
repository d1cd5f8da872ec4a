// CVODE transient solver: a free mass hitting a Kelvin-Voigt contact against the closed form
// (Schwager & Poeschel 2007), and energy bookkeeping and episodes of a bouncing cantilever.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "dynamics/cvode/cvode_solver.hpp"
#include "fem/system.hpp"
#include "transient_fixtures.hpp"

namespace vi {
namespace {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

double total(const EnergyLedger& e) { return e.kinetic + e.strain + e.contact_spring; }

// Mass m at distance h from a support (below for sign = +1, above for -1, surface at 0), moving
// towards it at v0; K = 0, so only the contact acts.
constexpr double kMass = 1e-11, kContact = 50.0;
double falling_mass_damper(double zeta) { return zeta * 2.0 * std::sqrt(kContact * kMass); }
TransientProblem falling_mass(double zeta, double sign = 1.0) {
    const double v0 = 0.1, h = 0.2e-6;
    TransientProblem p = test::one_dof(kMass, 0.0);
    p.forces.push_back(test::support(0, 0, sign, 0.0, kContact, falling_mass_damper(zeta)));
    p.q0 = Eigen::VectorXd::Constant(1, sign * h);
    p.v0 = Eigen::VectorXd::Constant(1, -sign * v0);
    p.modes0 = {0};
    p.t_end = h / v0 + 2.0 * std::numbers::pi * std::sqrt(kMass / kContact);
    p.output_step = p.t_end / 100;
    return p;
}

// Kelvin-Voigt contact with the no-tension rule: w_n t_c = (pi - 2 asin zeta) / sqrt(1 - zeta^2),
// e = exp(-zeta w_n t_c). Measured (rtol 1e-10): t_c 2e-11..2e-10, e 1e-9..5e-9, impulse 3e-10..2e-9.
TEST(CvodeSolver, FreeMassImpactMatchesKelvinVoigtClosedForm) {
    for (const auto& [zeta, sign] : {std::pair{0.0, 1.0}, {0.1, 1.0}, {0.5, 1.0}, {0.1, -1.0}}) {
        const TransientProblem p = falling_mass(zeta, sign);
        const double m = kMass, Kc = kContact, v0 = std::abs(p.v0[0]);
        const double wn = std::sqrt(Kc / m);
        const double tc = (std::numbers::pi - 2.0 * std::asin(zeta)) / std::sqrt(1.0 - zeta * zeta) / wn;
        const double e = std::exp(-zeta * wn * tc);
        const TransientResult r = solve_cvode(p);
        ASSERT_EQ(r.episodes.size(), 1u) << "zeta = " << zeta;
        const ContactEpisode& ep = r.episodes[0];
        EXPECT_LT(rel(ep.t_on, std::abs(p.q0[0]) / v0), 1e-9) << "zeta = " << zeta;
        EXPECT_LT(rel(ep.t_off - ep.t_on, tc), 1e-7) << "zeta = " << zeta;
        EXPECT_LT(rel(std::abs(ep.v_out / ep.v_in), e), 1e-7) << "zeta = " << zeta;
        EXPECT_LT(rel(ep.impulse, m * v0 * (1.0 + e)), 1e-7) << "zeta = " << zeta;
        EXPECT_LT(rel(ep.v_in, p.v0[0]), 1e-9);
        EXPECT_LT(ep.v_out * ep.v_in, 0.0);
        EXPECT_FALSE(ep.closed_at_end);
        if (zeta == 0.0) {
            EXPECT_LT(rel(ep.peak_penetration, v0 / wn), 1e-7);
            EXPECT_LT(rel(ep.peak_force, Kc * v0 / wn), 1e-7);
        } else {
            EXPECT_GE(ep.peak_force, falling_mass_damper(zeta) * v0 * (1.0 - 1e-9));  // F at onset
        }
        // The mass leaves with e v0; the lost kinetic energy is the contact dissipation.
        const double k0 = 0.5 * m * v0 * v0;
        EXPECT_LT(rel(r.final_energy.kinetic, e * e * k0), 1e-7);
        EXPECT_LT(std::abs(k0 - r.final_energy.kinetic - r.final_energy.contact_dissipated) / k0, 1e-7);
        EXPECT_EQ(r.history.t.size(), 101u);
        EXPECT_EQ(r.history.contact_force[0].size(), 101u);
        EXPECT_EQ(r.stats.method, "cvode");
        EXPECT_EQ(r.stats.events, 2);
    }
}

// Prestressed start: the mass rests at rest on the support with penetration d0 (closed at t = 0);
// undamped, it is pushed out and leaves when d = 0 after a quarter period with speed w d0.
TEST(CvodeSolver, ContactClosedAtStartOpensAfterQuarterPeriod) {
    TransientProblem p = falling_mass(0.0);
    const double d0 = 1e-8, wn = std::sqrt(kContact / kMass);
    p.q0[0] = -d0;
    p.v0[0] = 0.0;
    p.modes0 = {1};
    p.t_end = 3.0 / wn;
    const TransientResult r = solve_cvode(p);
    ASSERT_EQ(r.episodes.size(), 1u);
    EXPECT_EQ(r.episodes[0].t_on, 0.0);
    EXPECT_LT(rel(r.episodes[0].t_off, 0.5 * std::numbers::pi / wn), 1e-8);
    EXPECT_LT(rel(r.episodes[0].v_out, wn * d0), 1e-8);
    EXPECT_LT(rel(r.episodes[0].peak_force, kContact * d0), 1e-12);
    EXPECT_EQ(r.stats.events, 1);
    EXPECT_LT(rel(r.initial_energy.contact_spring, 0.5 * kContact * d0 * d0), 1e-12);
    EXPECT_EQ(r.initial_energy.contact_dissipated, 0.0);
}

// Mass-spring under a step load F from t_on: q = F/k (1 - cos w (t - t_on)) after, exactly 0 before
// (the load breakpoint is an integration stop; the jump must not leak into the step before it).
// The ledger: kinetic + strain = external work.
TEST(CvodeSolver, StepLoadBreakpointIsExact) {
    const double m = 1e-11, k = 10.0, F = 1e-6, w = std::sqrt(k / m), T = 2.0 * std::numbers::pi / w;
    TransientProblem p = test::one_dof(m, k);
    TimeFunction step;
    step.kind = TimeFunction::Kind::step;
    step.t_on = 0.37 * T;
    p.forces.push_back(test::load_on_first_dof(F, step));
    p.t_end = 3.0 * T;
    p.output_step = T / 50;
    const TransientResult r = solve_cvode(p);
    double worst = 0.0, ledger = 0.0;
    for (std::size_t i = 0; i < r.history.t.size(); ++i) {
        const double t = r.history.t[i];
        const double exact = t < step.t_on ? 0.0 : F / k * (1.0 - std::cos(w * (t - step.t_on)));
        worst = std::max(worst, std::abs(r.history.watched_v[i] - exact) / (2.0 * F / k));
        const EnergyLedger& e = r.history.energy[i];
        ledger = std::max(ledger, std::abs(e.kinetic + e.strain - e.external_work) / (2.0 * F * F / k));
        if (t < step.t_on) {
            EXPECT_EQ(r.history.watched_v[i], 0.0);
        }
    }
    EXPECT_LT(worst, 3e-8);  // measured 1e-8: BDF's phase error grows about 3e-9 per period
    EXPECT_LT(ledger, 1e-7);  // measured 1e-8
    EXPECT_EQ(r.history.t.size(), 151u);
}

// Mass-spring swinging from q0 = A at rest; a support below at -(1 - eps) A is barely reached: the
// penetration bump lasts ~ 2 sqrt(2 eps) / w, far shorter than a CVODE step. It must be found
// (CVODE's root finder, narrowing on the root of dd/dt at the lowest point, steps into the bump;
// the solver's own guard at that root catches the rest). At eps = 1e-9 the bump is as deep as the
// integration error (about 1e-9 A after half a period) and may be missed: grazing is resolved down
// to the accuracy of the integration, not below.
TEST(CvodeSolver, GrazingContactIsNotMissed) {
    const double m = 1e-11, k = 10.0, A = 1e-6, w = std::sqrt(k / m);
    for (double eps : {1e-4, 1e-6, 1e-8}) {
        TransientProblem p = test::one_dof(m, k);
        p.q0 = Eigen::VectorXd::Constant(1, A);
        p.forces.push_back(test::support(0, 0, 1.0, -(1.0 - eps) * A, 1e3 * k, 0.0));
        p.t_end = 0.75 * 2.0 * std::numbers::pi / w;
        p.output_step = p.t_end / 10;
        const TransientResult r = solve_cvode(p);
        ASSERT_EQ(r.episodes.size(), 1u) << "eps = " << eps;
        const double t_on = (std::numbers::pi - std::acos(1.0 - eps)) / w;
        // The onset is ill-conditioned near grazing: a displacement error delta moves it by
        // delta / (A w sqrt(2 eps)). Measured: 7e-6 relative at eps = 1e-8.
        EXPECT_LT(rel(r.episodes[0].t_on, t_on), 1e-8 / std::sqrt(eps)) << "eps = " << eps;
        EXPECT_GT(r.episodes[0].peak_penetration, 0.0);
        EXPECT_LT(r.episodes[0].peak_penetration, eps * A);
        EXPECT_LT(r.episodes[0].t_off - r.episodes[0].t_on, 4.0 * std::sqrt(2.0 * eps) / w);
    }
}

// The paper's cantilever (bending DOFs), one contact at the tip with zero gap, released from rest
// in its static shape under a tip force with the tip 1 um up.
TransientProblem bouncing_cantilever(int elements, double alpha, double beta, double Cc) {
    const Case c = test::paper_cantilever(elements);
    const System s = build_system(c);
    TransientProblem p;
    p.M = submatrix(s.M, s.bending);
    p.K = submatrix(s.K, s.bending);
    const int tip_reduced = s.reduced_of[global_dof(s.mesh.node_count() - 1, 1)];
    p.watched_dof = static_cast<int>(std::find(s.bending.begin(), s.bending.end(), tip_reduced) - s.bending.begin());
    Eigen::VectorXd f = Eigen::VectorXd::Zero(p.size());
    f[p.watched_dof] = 1.0;
    p.q0 = Eigen::MatrixXd(p.K).ldlt().solve(f);
    p.q0 *= 1e-6 / p.q0[p.watched_dof];
    p.v0 = Eigen::VectorXd::Zero(p.size());
    p.forces.push_back(test::support(0, p.watched_dof, 1.0, 0.0, 50.0, Cc, c.beam.length));
    p.modes0 = {0};
    p.alpha = alpha;
    p.beta = beta;
    p.t_end = 145e-6;
    p.output_step = 0.1e-6;
    return p;
}

void expect_sane_episodes(const TransientResult& r) {
    for (const ContactEpisode& ep : r.episodes) {
        EXPECT_GT(ep.t_off, ep.t_on);
        EXPECT_GT(ep.peak_force, 0.0);
        EXPECT_GT(ep.peak_penetration, 0.0);
        EXPECT_GT(ep.impulse, 0.0);
        EXPECT_LT(ep.v_in, 0.0);
        if (!ep.closed_at_end) {
            EXPECT_GT(ep.v_out, 0.0);
        }
    }
    for (std::size_t i = 1; i < r.episodes.size(); ++i) EXPECT_GE(r.episodes[i].t_on, r.episodes[i - 1].t_off);
}

// Undamped, kinetic + strain + contact spring is conserved through the impacts. BDF is dissipative
// and an undamped FE beam keeps every mode the impacts excite, so CVODE needs steps that resolve
// the highest mode. With m = 2 elements and rtol 1e-11 (130 us: 21 episodes): drift 6.6e-9 in
// 3.6e5 steps (docs/model.md §13 on why the modal tolerances are set as they are).
TEST(CvodeSolver, UndampedBeamConservesEnergyThroughImpacts) {
    const TransientProblem p = bouncing_cantilever(2, 0.0, 0.0, 0.0);
    CvodeOptions o;
    o.rtol = 1e-11;
    const TransientResult r = solve_cvode(p, {}, o);
    EXPECT_GT(r.episodes.size(), 20u);
    const double e0 = total(r.initial_energy);
    double worst = 0.0;
    for (const EnergyLedger& e : r.history.energy) worst = std::max(worst, std::abs(total(e) - e0) / e0);
    EXPECT_LT(worst, 1e-7);
    EXPECT_LT(std::abs(total(r.final_energy) - e0) / e0, 1e-7);
    EXPECT_EQ(r.final_energy.rayleigh_dissipated, 0.0);
    EXPECT_LT(std::abs(r.final_energy.contact_dissipated), 1e-30);
    expect_sane_episodes(r);
}

// With Rayleigh and contact damping (m = 10): lost energy = Rayleigh + contact dissipation at every
// sample. Measured (130 us): 21 episodes, 3.6e-10 relative, 8.8e4 steps, 1.1 s.
TEST(CvodeSolver, DampedBeamLedgerBalancesAndEpisodesAreSane) {
    const double w1 = 7.15e5;  // about the first circular frequency of the cantilever [rad/s]
    const TransientProblem p = bouncing_cantilever(10, 0.02 * w1, 0.002 / w1, 5e-6);
    const TransientResult r = solve_cvode(p);
    EXPECT_GT(r.episodes.size(), 20u);
    const double e0 = total(r.initial_energy);
    double worst = 0.0;
    for (const EnergyLedger& e : r.history.energy) {
        const double balance = e0 - total(e) - e.rayleigh_dissipated - e.contact_dissipated;
        worst = std::max(worst, std::abs(balance) / e0);
    }
    const EnergyLedger& ef = r.final_energy;
    EXPECT_GT(ef.rayleigh_dissipated, 0.0);
    EXPECT_GT(ef.contact_dissipated, 0.0);
    EXPECT_LT(total(ef), 1e-3 * e0);
    EXPECT_LT(std::abs(e0 - total(ef) - ef.rayleigh_dissipated - ef.contact_dissipated) / e0, 1e-7);
    EXPECT_LT(worst, 1e-7);
    expect_sane_episodes(r);
    // Every sampled force is that of a closed contact (>= 0), and zero when open.
    for (double f : r.history.contact_force[0]) EXPECT_GE(f, -1e-12);
}

// The same two ledgers with the state in the FE DOFs (CvodeOptions::State::nodal): kinetic and
// strain energy as quadratic forms of M and K, the Rayleigh integrand v^T C v.
TEST(CvodeSolver, LedgersBalanceWithTheStateInTheFeDofs) {
    CvodeOptions o;
    o.state = CvodeOptions::State::nodal;
    o.rtol = 1e-11;
    const TransientResult undamped = solve_cvode(bouncing_cantilever(2, 0.0, 0.0, 0.0), {}, o);
    ASSERT_TRUE(undamped.stats.nodal_state);
    EXPECT_GT(undamped.episodes.size(), 20u);
    const double e0 = total(undamped.initial_energy);
    double worst = 0.0;
    for (const EnergyLedger& e : undamped.history.energy) worst = std::max(worst, std::abs(total(e) - e0) / e0);
    EXPECT_LT(worst, 1e-7);
    EXPECT_EQ(undamped.final_energy.rayleigh_dissipated, 0.0);
    expect_sane_episodes(undamped);

    const double w1 = 7.15e5;  // about the first circular frequency of the cantilever [rad/s]
    o.rtol = 1e-10;
    const TransientResult damped = solve_cvode(bouncing_cantilever(10, 0.02 * w1, 0.002 / w1, 5e-6), {}, o);
    ASSERT_TRUE(damped.stats.nodal_state);
    EXPECT_GT(damped.episodes.size(), 20u);
    const double d0 = total(damped.initial_energy);
    worst = 0.0;
    for (const EnergyLedger& e : damped.history.energy) {
        worst = std::max(worst, std::abs(d0 - total(e) - e.rayleigh_dissipated - e.contact_dissipated) / d0);
    }
    EXPECT_GT(damped.final_energy.rayleigh_dissipated, 0.0);
    EXPECT_GT(damped.final_energy.contact_dissipated, 0.0);
    EXPECT_LT(worst, 1e-7);
    expect_sane_episodes(damped);
}

TEST(CvodeSolver, RejectsInconsistentProblems) {
    TransientProblem p = falling_mass(0.0);
    p.watched_dof = 3;
    EXPECT_THROW((void)solve_cvode(p), std::invalid_argument);
    p = falling_mass(0.0);
    p.t_end = 0.0;
    EXPECT_THROW((void)solve_cvode(p), std::invalid_argument);
}

TEST(CvodeSolver, StepBudgetExhaustedThrows) {
    TransientOptions o;
    o.max_steps = 20;
    EXPECT_THROW((void)solve_cvode(bouncing_cantilever(10, 0.0, 0.0, 0.0), o), std::runtime_error);
}

}  // namespace
}  // namespace vi
