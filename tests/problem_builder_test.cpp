// From Case to PiecewiseLinearProblem: the static step and equilibrium against closed forms (a cantilever's
// tip stiffness 3EI/l^3 in series or parallel with the support spring), contact damping from a
// damping ratio, Rayleigh damping from ratios, initial velocities, loads, and the bad starts.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dynamics/piecewise_linear_form.hpp"
#include "dynamics/transient_start.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "modal/modal_analysis.hpp"
#include "paper_cases.hpp"

namespace {

using vi::BuiltProblem;
using vi::Case;

// 3EI/l^3 of the paper's cantilever [N/m].
double tip_stiffness(const Case& c) {
    return 3.0 * c.material.youngs_modulus * c.beam.second_moment() / std::pow(c.beam.length, 3);
}

// The paper cantilever (m = 50) with a support below its tip (Kc = 50 N/m), lifted at the tip.
Case lifted_cantilever(double displacement, double prestress = 0.0) {
    Case c = vi::test::paper_cantilever(50, 1.0);
    c.supports[0].surface = prestress;
    c.initial.kind = vi::InitialState::Kind::displacement;
    c.initial.position = 1.0;
    c.initial.displacement = displacement;
    return c;
}

vi::Support support_at(double position, vi::Side side, double surface) {
    vi::Support s;
    s.position = position;
    s.side = side;
    s.surface = surface;
    s.stiffness = 50.0;
    return s;
}

// The problem as the exact solver sees it: each force element's piecewise-linear form.
vi::PiecewiseLinearProblem pl(const BuiltProblem& b) { return vi::piecewise_linear_form(b.problem); }

// The message of the InputError building c throws, or "built".
std::string build_error(const Case& c) {
    try {
        (void)vi::build_transient_problem(c);
    } catch (const vi::InputError& e) {
        return e.what();
    }
    return "built";
}

TEST(ProblemBuilder, TipLiftedAboveAZeroGapSupport) {
    const Case c = lifted_cantilever(1e-6);
    const BuiltProblem b = vi::build_transient_problem(c);
    const vi::PiecewiseLinearProblem p = vi::piecewise_linear_form(b.problem);  // what the elements say of themselves
    ASSERT_EQ(p.size(), 100);  // 51 nodes x (v, theta), the clamp's two removed
    EXPECT_EQ(p.K.rows(), 100);
    EXPECT_EQ(p.q0.size(), 100);
    ASSERT_EQ(p.tip_dof, 98);  // v of the last node
    EXPECT_NEAR(p.q0[p.tip_dof], 1e-6, 1e-18);
    EXPECT_NEAR(b.start.static_force_n, tip_stiffness(c) * 1e-6, 1e-9 * tip_stiffness(c) * 1e-6);
    EXPECT_NEAR(b.start.y0_m, 1e-6, 1e-18);
    EXPECT_EQ(b.start.q_equilibrium.norm(), 0.0);
    ASSERT_EQ(p.contacts.size(), 1u);
    EXPECT_EQ(p.contacts[0].dof, p.tip_dof);
    EXPECT_EQ(p.contacts[0].sign, 1.0);
    EXPECT_EQ(p.contacts[0].surface, 0.0);
    EXPECT_DOUBLE_EQ(p.contacts[0].x, 117e-6);
    EXPECT_EQ(p.active0, std::vector<bool>{false});
    EXPECT_EQ(p.v0.size(), 100);
    EXPECT_EQ(p.v0.norm(), 0.0);
    EXPECT_EQ(p.alpha, 0.0);
    EXPECT_EQ(p.beta, 0.0);
}

TEST(ProblemBuilder, PrestressedTipRestsOnItsSupport) {
    const double s = 0.5e-6;
    const double kb = tip_stiffness(lifted_cantilever(0.0));
    const double kc = 50.0;
    const double v_eq = kc * s / (kc + kb);  // the beam and the support spring in series
    Case c = lifted_cantilever(0.0, s);
    c.initial.kind = vi::InitialState::Kind::rest;
    BuiltProblem b = vi::build_transient_problem(c);
    EXPECT_NEAR(b.start.q_equilibrium[b.problem.tip_dof], v_eq, 1e-9 * v_eq);
    EXPECT_EQ(pl(b).active0, std::vector<bool>{true});
    EXPECT_EQ(b.problem.q0, b.start.q_equilibrium);
    EXPECT_EQ(b.start.static_force_n, 0.0);

    // A lift past the surface opens the contact: only the beam resists the force.
    b = vi::build_transient_problem(lifted_cantilever(1e-6, s));
    const double v_eq_fe = b.start.q_equilibrium[b.problem.tip_dof];
    EXPECT_NEAR(b.problem.q0[b.problem.tip_dof], v_eq_fe + 1e-6, 1e-12 * (v_eq_fe + 1e-6));
    EXPECT_NEAR(b.start.static_force_n, kb * (v_eq + 1e-6), 1e-9 * kb * (v_eq + 1e-6));
    EXPECT_EQ(pl(b).active0, std::vector<bool>{false});
    EXPECT_NEAR(b.start.y0_m, 1e-6, 1e-15);

    // A small lift keeps it closed: beam and spring in parallel.
    b = vi::build_transient_problem(lifted_cantilever(1e-8, s));
    EXPECT_NEAR(b.start.static_force_n, (kb + kc) * 1e-8, 1e-9 * (kb + kc) * 1e-8);
    EXPECT_EQ(pl(b).active0, std::vector<bool>{true});
}

TEST(ProblemBuilder, PrestressedSupportAboveAndClampedClampedBeam) {
    Case c = vi::test::paper_cantilever(50);
    c.initial.kind = vi::InitialState::Kind::rest;
    c.supports.push_back(support_at(1.0, vi::Side::above, 0.5e-6));
    const double kb = tip_stiffness(c);
    BuiltProblem b = vi::build_transient_problem(c);
    EXPECT_EQ(pl(b).contacts[0].sign, -1.0);
    EXPECT_EQ(pl(b).contacts[0].surface, -0.5e-6);
    EXPECT_NEAR(b.start.q_equilibrium[b.problem.tip_dof], -50.0 * 0.5e-6 / (50.0 + kb), 1e-15);

    Case cc = vi::test::clamped_clamped(50);
    cc.initial.kind = vi::InitialState::Kind::rest;
    cc.supports.push_back(support_at(0.5, vi::Side::below, 0.5e-6));
    const double k_mid = 192.0 * cc.material.youngs_modulus * cc.beam.second_moment() / std::pow(cc.beam.length, 3);
    b = vi::build_transient_problem(cc);
    ASSERT_EQ(b.problem.tip_dof, pl(b).contacts[0].dof);  // no free end: watch mid-span
    EXPECT_NEAR(b.start.q_equilibrium[b.problem.tip_dof], 50.0 * 0.5e-6 / (50.0 + k_mid), 1e-9 * 0.5e-6);
}

TEST(ProblemBuilder, LiftIntoASupportAboveIsAnInputError) {
    Case c = lifted_cantilever(1e-6);
    c.supports.push_back(support_at(1.0, vi::Side::above, -0.5e-6));  // gap 0.5 um above the tip
    const std::string what = build_error(c);
    EXPECT_EQ(what.rfind("initial.displacement: the initial state penetrates supports[1] (d = 5e-07 m", 0), 0u) << what;

    c.initial = {};
    c.initial.kind = vi::InitialState::Kind::force;
    c.initial.force = 1e-5;  // lifts a free tip by about 1.3 um
    EXPECT_EQ(build_error(c).rfind("initial.force: the initial state penetrates supports[1]", 0), 0u) << build_error(c);

    c.supports[1].surface = -1.5e-6;  // a gap large enough
    c.initial.kind = vi::InitialState::Kind::displacement;
    c.initial.displacement = 1e-6;
    EXPECT_EQ(build_error(c), "built");
}

TEST(ProblemBuilder, ForceStep) {
    Case c = lifted_cantilever(0.0);
    c.initial.kind = vi::InitialState::Kind::force;
    c.initial.force = 2e-6;
    const BuiltProblem b = vi::build_transient_problem(c);
    const double y = 2e-6 / tip_stiffness(c);
    EXPECT_NEAR(b.problem.q0[b.problem.tip_dof], y, 1e-9 * y);
    EXPECT_NEAR(b.start.y0_m, y, 1e-9 * y);
    EXPECT_EQ(b.start.static_force_n, 2e-6);
}

TEST(ProblemBuilder, ContactDampingFromARatio) {
    Case c = lifted_cantilever(1e-6);
    c.supports[0].damping_ratio = 0.1;
    const BuiltProblem b = vi::build_transient_problem(c);
    const double rho_a_l = c.material.density * c.beam.area() * c.beam.length;
    const double expected = 2.0 * 0.1 * std::sqrt(50.0 * rho_a_l / 4.0);  // phi1(l)^2 = 4 / (rho A l)
    EXPECT_NEAR(b.model.contact_damping[0], expected, 1e-6 * expected);
    EXPECT_EQ(pl(b).contacts[0].damping, b.model.contact_damping[0]);
    EXPECT_EQ(b.model.contact_stiffness, std::vector<double>{50.0});
}

TEST(ProblemBuilder, RayleighFromRatiosAtTheChosenModes) {
    Case c = lifted_cantilever(1e-6);
    c.damping.from_ratios = true;
    c.damping.ratio1 = 0.01;
    c.damping.ratio2 = 0.03;
    c.damping.mode1 = 1;
    c.damping.mode2 = 3;
    const BuiltProblem b = vi::build_transient_problem(c);
    const vi::ModalResult modes = vi::analyse_modes(vi::build_system(c), 3);
    EXPECT_NEAR(b.model.omega1, modes.bending[0].omega, 1e-9 * b.model.omega1);
    EXPECT_NEAR(vi::rayleigh_ratio(b.model.rayleigh, modes.bending[0].omega), 0.01, 1e-9);
    EXPECT_NEAR(vi::rayleigh_ratio(b.model.rayleigh, modes.bending[2].omega), 0.03, 1e-9);
    EXPECT_EQ(b.problem.alpha, b.model.rayleigh.alpha);
    EXPECT_EQ(b.problem.beta, b.model.rayleigh.beta);

    c.damping = {};
    c.damping.alpha = 100.0;
    c.damping.beta = 1e-10;
    const BuiltProblem d = vi::build_transient_problem(c);
    EXPECT_EQ(d.problem.alpha, 100.0);
    EXPECT_EQ(d.problem.beta, 1e-10);
}

TEST(ProblemBuilder, InitialVelocities) {
    Case c = lifted_cantilever(1e-6);
    c.initial.velocity_kind = vi::InitialState::Velocity::uniform;
    c.initial.velocity = -0.2;
    BuiltProblem b = vi::build_transient_problem(c);
    for (Eigen::Index i = 0; i < b.problem.size(); ++i) EXPECT_EQ(b.problem.v0[i], i % 2 == 0 ? -0.2 : 0.0) << i;

    c.initial.velocity_kind = vi::InitialState::Velocity::mode;
    c.initial.velocity_mode = 2;
    b = vi::build_transient_problem(c);
    EXPECT_NEAR(b.problem.v0[b.problem.tip_dof], -0.2, 1e-12);
    // Along mode 2: K v0 = omega2^2 M v0.
    const Eigen::VectorXd kv = b.problem.K * b.problem.v0;
    const Eigen::VectorXd mv = b.problem.M * b.problem.v0;
    const double w2 = kv.dot(b.problem.v0) / mv.dot(b.problem.v0);
    EXPECT_LT((kv - w2 * mv).norm(), 1e-8 * kv.norm());
    EXPECT_GT(w2, 2.0 * b.model.omega1 * b.model.omega1);

    c.initial.velocity_mode = 500;
    EXPECT_EQ(build_error(c).rfind("initial.velocity_mode: mode 500 does not exist", 0), 0u) << build_error(c);
}

TEST(ProblemBuilder, LoadsAndSampling) {
    Case c = lifted_cantilever(1e-6);
    vi::PointLoad load;
    load.position = 0.5;
    load.amplitude = 3e-6;
    load.time.kind = vi::TimeFunction::Kind::step;
    load.time.t_on = 1e-6;
    c.loads.push_back(load);
    c.solver.horizon = 100e-6;
    BuiltProblem b = vi::build_transient_problem(c);
    ASSERT_EQ(pl(b).loads.size(), 1u);
    const vi::LoadTerm t = pl(b).loads[0];
    EXPECT_EQ(t.amplitude, 3e-6);
    EXPECT_EQ(t.time.kind, vi::TimeFunction::Kind::step);
    EXPECT_EQ(t.shape.size(), 100);
    EXPECT_NEAR(t.shape[48], 1.0, 1e-12);  // x = l/2 is node 25: v of node 25 is bending DOF 48
    EXPECT_NEAR(t.shape.sum(), 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(b.problem.t_end, 100e-6);
    EXPECT_DOUBLE_EQ(b.problem.output_step, 100e-6 / 2000.0);
    c.solver.output_step = 1e-8;
    b = vi::build_transient_problem(c);
    EXPECT_EQ(b.problem.output_step, 1e-8);
}

TEST(ProblemBuilder, ThePaperExampleFile) {
    const Case c = vi::read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    const BuiltProblem b = vi::build_transient_problem(c);
    EXPECT_NEAR(b.problem.q0[b.problem.tip_dof], 1e-6, 1e-18);
    EXPECT_EQ(pl(b).active0, std::vector<bool>{false});
    EXPECT_DOUBLE_EQ(b.problem.t_end, 150e-6);
    EXPECT_DOUBLE_EQ(b.problem.output_step, 10e-9);
    EXPECT_GT(b.model.omega1, 0.0);
}

TEST(ProblemBuilder, BadCasesAreInputErrors) {
    Case c = lifted_cantilever(1e-6);
    c.supports[0].position = 1e-12;  // shares the clamp's node
    EXPECT_EQ(build_error(c).rfind("supports[0].position: the support sits on a node held by an end condition", 0), 0u)
        << build_error(c);
    c = lifted_cantilever(1e-6);
    c.initial.position = 0.0;
    EXPECT_EQ(build_error(c), "initial.position: must lie in (0, 1] (x/l)");
    c = lifted_cantilever(1e-6);
    c.supports[0].stiffness = -1.0;
    EXPECT_EQ(build_error(c), "supports[0].stiffness: must be positive");
}

}  // namespace
