// Switching transients (docs/electrostatics.md §5-§6): the one-degree-of-freedom parallel plate under
// a voltage step against its closed forms (step pull-in at sqrt(27/32) V_PI, closing time by exact
// quadrature), the switching ledger of the cantilever switch, and `pullin --dynamic` on it.

#include <gtest/gtest.h>

#include <Eigen/SparseCore>
#include <nlohmann/json.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>
#include <variant>
#include <vector>
#include <string>

#include "dynamics/cvode/cvode_solver.hpp"
#include "fem/gauss_legendre.hpp"
#include "forces/electrostatic_pad.hpp"
#include "forces/kelvin_voigt_contact.hpp"
#include "impacts/dynamic_pullin.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "sweep/columns.hpp"
#include "validation/electrostatic_references.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace {

// The plate: k, m, gap g, area A = w L; a stiff stop at travel g_c; undamped.
struct Plate {
    double k = 10.0, m = 1e-10, g = 2e-6, w = 100e-6, L = 100e-6;
    double gc = 0.9 * g;
    [[nodiscard]] double area() const { return w * L; }
    [[nodiscard]] double omega0() const { return std::sqrt(k / m); }
    [[nodiscard]] double v_pi() const { return std::sqrt(8 * k * g * g * g / (27 * kEpsilon0 * area())); }
};

// The plate at rest under a step to `volts` at t = 0 (a constant voltage from rest is that step),
// with a Kelvin-Voigt stop at travel g_c, over `periods` periods of omega0. The stop is 1e6 k stiff
// (above the electrostatic softening eps0 A V^2 / (g - g_c)^3 up to V = 10 V_PI) and damped at half
// its critical value, so a plate that reaches it settles there; neither matters before it closes.
TransientProblem plate_problem(const Plate& p, double volts, double periods, bool stop = true) {
    const double kc = 1e6 * p.k;
    TransientProblem tp;
    tp.M.resize(1, 1);
    tp.M.insert(0, 0) = p.m;
    tp.K.resize(1, 1);
    tp.K.insert(0, 0) = p.k;
    tp.forces.push_back(parallel_plate_pad(p.g, p.w, p.L, volts, TimeFunction{}));
    if (stop) tp.forces.push_back(std::make_shared<const KelvinVoigtContact>("supports[0]", 0, 1.0, -p.gc, kc, std::sqrt(kc * p.m), 0.0));
    tp.q0 = Eigen::VectorXd::Zero(1);
    tp.v0 = Eigen::VectorXd::Zero(1);
    tp.watched_dof = 0;
    tp.t_end = periods * 2 * std::numbers::pi / p.omega0();
    return tp;
}

// Time from rest to travel x1 under V, undamped: t = int_0^x1 dx / sqrt((2/m) E(x)) with
// E(x) = eps0 A V^2 / 2 (1/(g - x) - 1/g) - k x^2 / 2; x = u^2 removes the endpoint singularity:
// t = int_0^sqrt(x1) 2 du / sqrt((2/m) (eps0 A V^2 / (2 g (g - u^2)) - k u^2 / 2)), smooth in u.
// Composite Gauss-Legendre, `panels` panels of 20 points.
double closing_time_quadrature(const Plate& p, double volts, double x1, int panels) {
    const QuadratureRule r = gauss_legendre(20);
    const double b = std::sqrt(x1);
    double t = 0.0;
    for (int i = 0; i < panels; ++i) {
        for (std::size_t j = 0; j < r.nodes.size(); ++j) {
            const double u = b * (i + r.nodes[j]) / panels;
            const double x = u * u;
            const double e_over_x = kEpsilon0 * p.area() * volts * volts / (2 * p.g * (p.g - x)) - p.k * x / 2;
            t += r.weights[j] * b / panels * 2 / std::sqrt(2 / p.m * e_over_x);
        }
    }
    return t;
}

std::string sci(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3e", x);
    return buf;
}

StepTrial plate_trial(const Plate& p, double volts, double rtol, double periods) {
    CvodeOptions o;
    o.rtol = rtol;
    const TransientResult r = solve_cvode(plate_problem(p, volts, periods), {}, o);
    StepTrial t;
    t.voltage = volts;
    t.closes = !r.episodes.empty();
    if (t.closes) t.closing_time = r.episodes.front().t_on;
    return t;
}

TEST(OneDofStep, PullsInAtSqrt27Over32OfTheStaticVoltage) {
    // Below the step pull-in the undamped plate swings to at most g/2 and back, so any contact with
    // the stop at 0.9 g is a pull-in. The bisection stops at a relative width of 1e-7; CVODE at rtol
    // 1e-10 places the turning point's energy to ~1e-9, so the 1e-6 checked below has room.
    const Plate p;
    StepBisectionOptions o;
    o.rel_width = 1e-7;
    o.bisections = 40;
    const StepBisection b = bisect_step_voltage([&](double v) { return plate_trial(p, v, 1e-10, 20); }, 0.8 * p.v_pi(),
                                                p.v_pi(), o);
    const double ratio = 0.5 * (b.lower + b.upper) / p.v_pi();
    RecordProperty("ratio_minus_closed_form", sci(ratio - std::sqrt(27.0 / 32.0)));
    EXPECT_NEAR(ratio, std::sqrt(27.0 / 32.0), 1e-6);
}

TEST(OneDofStep, ClosingTimeMatchesTheExactQuadrature) {
    const Plate p;
    for (double n : {2.0, 5.0, 10.0}) {
        const double v = n * p.v_pi();
        const double exact = closing_time_quadrature(p, v, p.gc, 64);
        // The quadrature has converged: halving the panels changes nothing at 1e-13.
        ASSERT_NEAR(closing_time_quadrature(p, v, p.gc, 32), exact, 1e-13 * exact);
        // A horizon just past the closing time (under half a period of omega0 at 2 V_PI and above).
        const StepTrial t = plate_trial(p, v, 1e-10, 0.5);
        ASSERT_TRUE(t.closing_time.has_value());
        const double err = (*t.closing_time - exact) / exact;
        RecordProperty("closing_time_rel_error_at_" + std::to_string(static_cast<int>(n)) + "_VPI", sci(err));
        EXPECT_LT(std::abs(err), 1e-6) << "V = " << n << " V_PI: CVODE " << *t.closing_time << " s, exact " << exact;
    }
}

// Without a stop the plate collapses onto the electrode: the pad's terminal mode ends the run where
// the air gap falls to kCollapseGapFraction of g, at the time the exact quadrature gives for a travel
// of (1 - kCollapseGapFraction) g.
TEST(OneDofCollapse, EndsAtTheElectrodeAtTheQuadratureTime) {
    const Plate p;
    const double travel = (1.0 - kCollapseGapFraction) * p.g;
    for (double n : {1.0, 2.0, 10.0}) {
        const double v = n * p.v_pi();
        const double exact = closing_time_quadrature(p, v, travel, 64);
        ASSERT_NEAR(closing_time_quadrature(p, v, travel, 32), exact, 1e-12 * exact);
        CvodeOptions o;
        o.rtol = 1e-10;
        const TransientResult r = solve_cvode(plate_problem(p, v, 20.0, false), TransientOptions{}, o);
        ASSERT_TRUE(r.ended_by.has_value()) << "V = " << n << " V_PI";
        EXPECT_EQ(r.ended_by->name, "electrodes[0]");
        EXPECT_EQ(r.ended_by->reading.outcome, "collapsed");
        EXPECT_NEAR(r.ended_by->reading.value, kCollapseGapFraction * p.g, 1e-6 * p.g);
        EXPECT_EQ(r.t_end, r.ended_by->t);
        const double err = (r.ended_by->t - exact) / exact;
        RecordProperty("collapse_time_rel_error_at_" + std::to_string(static_cast<int>(n)) + "_VPI", sci(err));
        std::printf("plate collapse at %g V_PI: %.9g s, quadrature %.9g s (%s), %d steps\n", n, r.ended_by->t, exact,
                    sci(err).c_str(), r.stats.steps);
        EXPECT_LT(std::abs(err), 1e-6) << "V = " << n << " V_PI";
    }
}

// The step pull-in without any stop: the collapse itself decides each trial.
TEST(OneDofCollapse, StepPullinWithoutAStopAtSqrt27Over32) {
    const Plate p;
    StepBisectionOptions o;
    o.rel_width = 1e-7;
    o.bisections = 40;
    const auto trial = [&](double v) {
        CvodeOptions co;
        co.rtol = 1e-10;
        const TransientResult r = solve_cvode(plate_problem(p, v, 20.0, false), TransientOptions{}, co);
        StepTrial t;
        t.voltage = v;
        t.closes = r.ended_by.has_value();
        return t;
    };
    const StepBisection b = bisect_step_voltage(trial, 0.8 * p.v_pi(), p.v_pi(), o);
    const double ratio = 0.5 * (b.lower + b.upper) / p.v_pi();
    RecordProperty("ratio_minus_closed_form", sci(ratio - std::sqrt(27.0 / 32.0)));
    EXPECT_NEAR(ratio, std::sqrt(27.0 / 32.0), 1e-6);
}

}  // namespace
}  // namespace vi

namespace vi {
namespace {

TimeFunction pulse_table(double t_on, double rise, double hold, double fall) {
    TimeFunction g;
    g.kind = TimeFunction::Kind::table;
    g.times = {t_on, t_on + rise, t_on + rise + hold, t_on + rise + hold + fall};
    g.values = {0.0, 1.0, 1.0, 0.0};
    return g;
}

TEST(SwitchingLedger, VoltageWindowOfEachWaveform) {
    Electrode e;
    e.voltage = 70.0;
    e.time = pulse_table(1e-6, 1e-6, 2e-6, 1e-6);
    VoltageWindow w = voltage_window({e});
    ASSERT_TRUE(w.on && w.off);
    EXPECT_NEAR(*w.on, 1e-6 + kVoltageOffFraction * 1e-6, 1e-18);     // 1 % up the rise
    EXPECT_NEAR(*w.off, 4e-6 + (1 - kVoltageOffFraction) * 1e-6, 1e-18);  // 1 % above zero on the fall
    e.time = TimeFunction{};
    e.time.kind = TimeFunction::Kind::step;
    e.time.t_on = 2e-6;
    w = voltage_window({e});
    EXPECT_EQ(w.on, 2e-6);
    EXPECT_FALSE(w.off);  // held
    e.time.kind = TimeFunction::Kind::harmonic;
    e.time.frequency_hz = 1e5;
    w = voltage_window({e});
    ASSERT_TRUE(w.on);
    // sin(2 pi f t) passes 0.01 at t = asin(0.01) / (2 pi f).
    EXPECT_NEAR(*w.on, std::asin(kVoltageOffFraction) / (2 * std::numbers::pi * 1e5), 1e-15);
    EXPECT_FALSE(w.off);
    e.voltage = 0.0;
    w = voltage_window({e});
    EXPECT_FALSE(w.on);
}

// The switch example: a 70 V step closes it; 9 episodes in 4 impacts over 50 us (docs/electrostatics.md §3).
TEST(SwitchingLedger, TheSwitchExampleClosesBouncesAndHolds) {
    const Case c = read_case_file(test::source_path("examples/switch/cantilever_switch.toml"));
    SimulationOptions o;
    o.history = false;
    const SimulationRun run = run_simulation(c, o);
    ASSERT_TRUE(run.switching.has_value());
    const SwitchingLedger& l = *run.switching;
    const auto& eps = run.result.episodes;
    ASSERT_GE(eps.size(), 2u);
    EXPECT_EQ(l.state, "closed") << l.reason;
    ASSERT_TRUE(l.closing_time && l.stable_contact);
    EXPECT_EQ(*l.closing_time, eps.front().t_on);
    EXPECT_NEAR(*l.closing_time, 3.17e-6, 0.01e-6);
    // The stable contact is the last episode (closed to the horizon); each before it is a bounce.
    EXPECT_EQ(*l.stable_contact, eps.back().t_on);
    EXPECT_EQ(l.bounces, static_cast<int>(eps.size()) - 1);
    ASSERT_EQ(l.contacts.size(), eps.size());
    EXPECT_LT(l.contacts.front().impact_velocity, 0.0);  // moving down onto the stop
    EXPECT_FALSE(l.release_time);
    EXPECT_NE(l.reason.find("never falls"), std::string::npos) << l.reason;
}

// The same switch under a 20 us pulse: it closes, and opens once the voltage is off (no adhesion).
TEST(SwitchingLedger, APulseClosesAndReleasesTheSwitch) {
    Case c = read_case_file(test::source_path("examples/switch/cantilever_switch.toml"));
    c.electrodes[0].time = pulse_table(0.0, 0.1e-6, 20e-6, 0.1e-6);
    c.solver.horizon = 40e-6;
    SimulationOptions o;
    o.history = false;
    const SimulationRun run = run_simulation(c, o);
    ASSERT_TRUE(run.switching.has_value());
    const SwitchingLedger& l = *run.switching;
    EXPECT_EQ(l.state, "released") << l.reason;
    ASSERT_TRUE(l.voltage.off && l.release_time && l.stable_contact);
    EXPECT_GT(*l.release_time, *l.voltage.off);
    EXPECT_EQ(*l.release_time, run.result.episodes.back().t_off);
    EXPECT_FALSE(run.result.episodes.back().closed_at_end);
    EXPECT_LT(*l.stable_contact, *l.voltage.off);
}

// Below the closing voltage the ledger says "never closed" instead of the run failing.
TEST(SwitchingLedger, ASwitchThatDoesNotCloseSaysSo) {
    Case c = read_case_file(test::source_path("examples/switch/cantilever_switch.toml"));
    c.electrodes[0].voltage = 30.0;
    c.solver.horizon = 20e-6;
    SimulationOptions o;
    o.history = false;
    const SimulationRun run = run_simulation(c, o);
    ASSERT_TRUE(run.switching.has_value());
    EXPECT_EQ(run.switching->state, "never_closed");
    EXPECT_FALSE(run.switching->closing_time);
}

}  // namespace
}  // namespace vi

namespace vi {
namespace {

// A simulate sweep has the switching ledger's four columns after the solver column, filled for a case
// with electrodes and empty without.
TEST(SwitchingLedger, SweepColumns) {
    const std::vector<SweepColumn> cols = sweep_result_columns(SweepAnalysis::simulate, 0);
    std::size_t at = 0;
    while (at < cols.size() && cols[at].name != "solver") ++at;
    ASSERT_LT(at + 4, cols.size());
    EXPECT_EQ(cols[at + 1].name, "closing_time_s");
    EXPECT_EQ(cols[at + 2].name, "bounces");
    EXPECT_EQ(cols[at + 3].name, "stable_contact_s");
    EXPECT_EQ(cols[at + 4].name, "release_time_s");

    Case c = read_case_file(test::source_path("examples/switch/cantilever_switch.toml"));
    c.solver.horizon = 20e-6;
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    const SimulationRun run = run_simulation(c, o);
    const std::vector<SweepCell> cells = simulate_cells(run);
    ASSERT_EQ(cells.size(), cols.size());
    EXPECT_EQ(std::get<double>(cells[at + 1]), *run.switching->closing_time);
    EXPECT_EQ(std::get<std::int64_t>(cells[at + 2]), run.switching->bounces);
    EXPECT_TRUE(std::holds_alternative<std::monostate>(cells[at + 4]));  // the voltage holds: no release

    SimulationRun plain = run;
    plain.switching.reset();
    const std::vector<SweepCell> none = simulate_cells(plain);
    for (std::size_t k = at + 1; k <= at + 4; ++k) EXPECT_TRUE(std::holds_alternative<std::monostate>(none[k])) << k;
}

}  // namespace
}  // namespace vi

namespace vi {
namespace {

// `pullin --dynamic` on the switch example, to a coarse bracket (each transient costs ~1 s): the
// ratio to the static pull-in lies below 1 and, for this damped (Q = 100) cantilever, near the 1-DOF
// undamped 0.9186 (docs/electrostatics.md §6 has the measured value).
TEST(DynamicPullin, TheSwitchExampleClosesBelowItsStaticPullin) {
    const std::string file = test::source_path("examples/switch/cantilever_switch.toml");
    const auto r = test::run_vibroimpact({"pullin", file, "--dynamic", "--rel-width", "1e-2", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out)["dynamic"];
    const double ratio = j["ratio_to_static"].get<double>();
    EXPECT_GT(ratio, 0.85);
    EXPECT_LT(ratio, 0.99);
    EXPECT_LE(j["upper_V"].get<double>() - j["lower_V"].get<double>(), 1e-2 * j["upper_V"].get<double>());
    EXPECT_GE(j["trials"].size(), 3u);
    EXPECT_TRUE(j["upper_closing_time_s"].is_number());
}

TEST(DynamicPullin, BadOptionsAreExitTwo) {
    const std::string file = test::source_path("examples/switch/cantilever_switch.toml");
    EXPECT_EQ(test::run_vibroimpact({"pullin", file, "--dynamic", "--horizon", "-3 us"}).exit_code, 2);
    EXPECT_EQ(test::run_vibroimpact({"pullin", file, "--dynamic", "--horizon", "3 kg"}).exit_code, 2);
    EXPECT_EQ(test::run_vibroimpact({"pullin", file, "--dynamic", "--rel-width", "0"}).exit_code, 2);
}

}  // namespace
}  // namespace vi
