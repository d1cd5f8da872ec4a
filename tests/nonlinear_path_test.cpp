// The nonlinear path (CVODE in modal coordinates) with a force the exact solver cannot take: a
// hardening cubic spring on one mass, against its period by quadrature of the energy integral (an
// independent method) and against energy conservation; the choice of solver; and the reduced-order
// option against the full model.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/exact/exact_solver.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "support/test_elements.hpp"

namespace vi {
namespace {

constexpr double kMass = 1e-11, kStiffness = 10.0, kCubic = 1e13, kAmplitude = 1e-6;

// m q'' + k q + k3 q^3 = 0 released at rest from q = A.
TransientProblem duffing(double t_end, double output_step) {
    TransientProblem p;
    p.M = Eigen::MatrixXd::Constant(1, 1, kMass).sparseView();
    p.K = Eigen::MatrixXd::Constant(1, 1, kStiffness).sparseView();
    p.forces.push_back(std::make_shared<test::CubicSpring>(0, kCubic));
    p.q0 = Eigen::VectorXd::Constant(1, kAmplitude);
    p.v0 = Eigen::VectorXd::Zero(1);
    p.tip_dof = 0;
    p.t_end = t_end;
    p.output_step = output_step;
    return p;
}

// T = 4 int_0^A dq / sqrt(2 (V(A) - V(q)) / m), V = k q^2 / 2 + k3 q^4 / 4. With q = A sin(theta) the
// integrand is smooth: T = 4 int_0^{pi/2} dtheta / sqrt((2/m) (k/2 + k3 A^2 (1 + sin^2 theta) / 4)),
// integrated by composite Simpson on 2000 panels (error far below 1e-12).
double duffing_period() {
    const int n = 2000;
    const double h = 0.5 * std::numbers::pi / n;
    auto f = [](double th) {
        const double s = std::sin(th);
        return 1.0 / std::sqrt(2.0 / kMass * (0.5 * kStiffness + 0.25 * kCubic * kAmplitude * kAmplitude * (1.0 + s * s)));
    };
    double sum = f(0.0) + f(0.5 * std::numbers::pi);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
    return 4.0 * sum * h / 3.0;
}

TEST(NonlinearPath, CubicSpringPeriodAndEnergy) {
    const double T = duffing_period();
    const double linear_period = 2.0 * std::numbers::pi * std::sqrt(kMass / kStiffness);
    ASSERT_LT(T, 0.8 * linear_period);  // the cubic term matters: a hardening spring shortens the period
    const TransientResult r = solve_cvode(duffing(3.2 * T, T / 4000.0));
    // Downward zero crossings of q, located by linear interpolation between samples (q'' = 0 there,
    // so the interpolation error is third order in the sample step).
    std::vector<double> crossings;
    const auto& t = r.history.t;
    const auto& q = r.history.tip_v;
    for (std::size_t i = 1; i < q.size(); ++i) {
        if (q[i - 1] > 0.0 && q[i] <= 0.0) crossings.push_back(t[i - 1] + q[i - 1] / (q[i - 1] - q[i]) * (t[i] - t[i - 1]));
    }
    ASSERT_GE(crossings.size(), 3u);
    const double measured = 0.5 * (crossings[2] - crossings[0]);
    EXPECT_LT(std::abs(measured / T - 1.0), 1e-7) << "period " << measured << " s against " << T << " s";
    // Conservative: kinetic + strain + the spring's stored quartic energy stays constant.
    const auto total = [](const EnergyLedger& e) { return e.kinetic + e.strain + e.contact_spring; };
    const double e0 = total(r.initial_energy);
    EXPECT_NEAR(e0, 0.5 * kStiffness * kAmplitude * kAmplitude + 0.25 * kCubic * std::pow(kAmplitude, 4), 1e-12 * e0);
    double worst = 0.0;
    for (const EnergyLedger& e : r.history.energy) worst = std::max(worst, std::abs(total(e) / e0 - 1.0));
    EXPECT_LT(worst, 1e-7);
    EXPECT_EQ(r.stats.method, "cvode");
}

TEST(NonlinearPath, TheExactSolverNamesTheElementItCannotTake) {
    try {
        (void)solve_exact(duffing(1e-6, 1e-8));
        FAIL() << "the exact solver took a cubic spring";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("solver.method: ", 0), 0u) << what;
        EXPECT_NE(what.find("springs[0] (cubic spring) is not"), std::string::npos) << what;
    }
}

Case paper_example(double horizon) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/paper/free_impact_tip.toml");
    c.solver.horizon = horizon;
    c.solver.method = SolverSettings::Method::automatic;
    return c;
}

TEST(NonlinearPath, AutomaticMethodTakesTheExactSolverForPiecewiseLinearForces) {
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    EXPECT_EQ(run_simulation(paper_example(10e-6), o).result.stats.method, "exact");
}

// The reduced-order model (N lowest modes, the static correction at the contact, the start) against
// the full model, both on CVODE at rtol 1e-10 over the first three impacts. Measured: N = 10 is
// within 5e-9 of the full model in T, T2, y_max and the first peak force; N = 3 misses the peak
// force by 6e-3 (the contact excites modes 4-10); the error falls as N grows.
TEST(NonlinearPath, ReducedOrderModelConvergesToTheFullModel) {
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    Case c = paper_example(20e-6);
    c.solver.method = SolverSettings::Method::cvode;
    const SimulationRun full = run_simulation(c, o);
    EXPECT_EQ(full.result.stats.basis_vectors, 100);
    auto error = [&](int modes) {
        c.solver.reduced_modes = modes;
        const SimulationRun rom = run_simulation(c, o);
        EXPECT_EQ(rom.result.stats.basis_modes, modes);
        EXPECT_GT(rom.result.stats.basis_vectors, modes);  // the static correction at the contact
        EXPECT_LT(rom.result.stats.initial_projection_error, 1e-12);  // the start is in the basis
        const auto rel = [](double a, double b) { return std::abs(a / b - 1.0); };
        return std::max({rel(*rom.summary.T_first, *full.summary.T_first), rel(*rom.summary.T2_first, *full.summary.T2_first),
                         rel(*rom.summary.y_max, *full.summary.y_max),
                         rel(rom.summary.impacts.front().peak_force, full.summary.impacts.front().peak_force)});
    };
    const double e3 = error(3), e5 = error(5), e10 = error(10);
    std::printf("reduced-order error against the full model: N = 3: %.1e, N = 5: %.1e, N = 10: %.1e\n", e3, e5, e10);
    EXPECT_GT(e3, 1e-4);
    EXPECT_LT(e5, e3);
    EXPECT_LT(e10, 1e-6);
}

}  // namespace
}  // namespace vi
