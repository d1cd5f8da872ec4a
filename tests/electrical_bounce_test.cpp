// The electrical bounce ledger (impacts/electrical_ledger.hpp) of a contact with a resistance model:
// a point mass on a Hertz dimple against the closed form of its impact, the switch example against
// its own mechanical ledger at thresholds above and below every closed resistance, independence
// from the output step, the summary's and the sweep's values, and the command's --r-on.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "dynamics/cvode/cvode_solver.hpp"
#include "forces/hertz_contact.hpp"
#include "impacts/electrical_ledger.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "report/contact_resistance.hpp"
#include "report/transient_output.hpp"
#include "support/run_command.hpp"
#include "sweep/columns.hpp"
#include "transient_fixtures.hpp"

namespace vi {
namespace electrical_test {

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

constexpr double kRadius = 2e-6, kMass = 1e-11, kRho = 2.2e-8;
double gold_k() { return hertz_stiffness(effective_modulus(79e9, 0.42, 79e9, 0.42), kRadius); }

// Holm's resistance of the elastic spot at penetration d: rho / (2 sqrt(R d)).
double holm(double d) { return kRho / (2.0 * std::sqrt(kRadius * d)); }

// A mass 0.1 um above an undamped gold dimple (Holm's resistance, threshold r_on), falling at v.
TransientProblem falling_mass(double v, double r_on) {
    const double h = 0.1e-6;
    ContactResistance m;
    m.resistivity = kRho;
    m.r_on = r_on;
    TransientProblem p = test::one_dof(kMass, 0.0);
    p.forces.push_back(std::make_shared<HertzContact>("supports[0]", 0, 1.0, 0.0, 0.0, gold_k(), 0.0, kRadius, m));
    p.q0 = Eigen::VectorXd::Constant(1, h);
    p.v0 = Eigen::VectorXd::Constant(1, -v);
    p.modes0 = {0};
    const double d_max = std::pow(5.0 * kMass * v * v / (4.0 * gold_k()), 0.4);
    p.t_end = h / v + 6.0 * d_max / v;
    p.output_step = p.t_end / 50;
    return p;
}

// Int_{u0}^1 du / sqrt(1 - u^(5/2)) by Simpson's rule in s, u = 1 - s^2 (the integrand
// 2 s / sqrt(1 - (1 - s^2)^(5/2)) is smooth, tending to 2 / sqrt(5/2) at s = 0).
double time_above(double u0) {
    const int n = 20000;
    const double top = std::sqrt(1.0 - u0);
    const auto f = [](double s) {
        if (s == 0.0) return 2.0 / std::sqrt(2.5);
        return 2.0 * s / std::sqrt(1.0 - std::pow(1.0 - s * s, 2.5));
    };
    double sum = f(0.0) + f(top);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(top * i / n);
    return sum * top / (3.0 * n);
}

CvodeOptions tight() {
    CvodeOptions o;
    o.rtol = 1e-12;
    return o;
}

// Undamped Hertz impact (Johnson 1985, §11.4): the mass reaches depth d at the time
// (d_max / v) Int_0^(d / d_max) du / sqrt(1 - u^(5/2)) after touching, so it conducts below
// r_on = R(d_on) for 2 (d_max / v) Int_(d_on / d_max)^1 du / sqrt(1 - u^(5/2)), centred on the
// impact; the smallest resistance is Holm's at d_max.
TEST(ElectricalBounce, PointMassConductsForTheClosedFormTime) {
    const double v = 0.5;
    const double d_max = std::pow(5.0 * kMass * v * v / (4.0 * gold_k()), 0.4);
    for (const double u_on : {0.25, 0.5, 0.9}) {
        SCOPED_TRACE("d_on / d_max = " + std::to_string(u_on));
        const TransientResult r = solve_cvode(falling_mass(v, holm(u_on * d_max)), {}, tight());
        ASSERT_EQ(r.episodes.size(), 1u);
        ASSERT_EQ(r.conduction.size(), 1u);
        const ContactConduction& c = r.conduction[0];
        ASSERT_EQ(c.stretches.size(), 1u);
        const ConductionStretch& s = c.stretches[0];
        const ContactEpisode& ep = r.episodes[0];
        const double t_c = ep.t_off - ep.t_on;
        EXPECT_LT(rel(s.t_off - s.t_on, 2.0 * d_max / v * time_above(u_on)), 1e-6);
        EXPECT_LT(std::abs(0.5 * (s.t_on + s.t_off) - 0.5 * (ep.t_on + ep.t_off)), 1e-6 * t_c);
        EXPECT_LT(rel(s.min_resistance, holm(d_max)), 1e-6);
        EXPECT_FALSE(s.on_at_end);
        EXPECT_TRUE(std::isinf(c.end_resistance));
        const std::optional<ElectricalLedger> l = electrical_ledger(c);
        ASSERT_TRUE(l);
        EXPECT_EQ(l->bounces, 1);  // the mass leaves: one opening, lasting to the end
        EXPECT_FALSE(l->openings[0].duration);
        EXPECT_FALSE(l->settle_time);
        EXPECT_EQ(*l->first_closure, s.t_on);
    }
    // Below Holm's resistance at d_max: never on.
    const TransientResult never = solve_cvode(falling_mass(v, 0.99 * holm(d_max)), {}, tight());
    ASSERT_EQ(never.conduction.size(), 1u);
    EXPECT_TRUE(never.conduction[0].stretches.empty());
    EXPECT_EQ(electrical_ledger(never.conduction[0])->bounces, 0);
    // Without a threshold: the end resistance alone, no ledger.
    const TransientResult none = solve_cvode(falling_mass(v, std::nan("")), {}, tight());
    ASSERT_EQ(none.conduction.size(), 1u);
    EXPECT_FALSE(electrical_ledger(none.conduction[0]));
}

Case switch_case(double r_on) {
    Case c = read_case_file(test::source_path("examples/switch/cantilever_switch_hertz.toml"));
    c.supports[0].params.numbers["r_on"] = r_on;
    return c;
}

SimulationRun run_quiet(const Case& c) {
    SimulationOptions o;
    o.energy = false;
    return run_simulation(c, o);
}

// The switch example bounces on its dimple and settles. With r_on above every closed resistance the
// oscilloscope sees every mechanical opening (each closure drops below r_on at once); below the
// smallest it never sees the contact on.
TEST(ElectricalBounce, SwitchMatchesItsMechanicalLedgerAtExtremeThresholds) {
    const SimulationRun high = run_quiet(switch_case(1e6));
    ASSERT_EQ(high.result.conduction.size(), 1u);
    const ContactConduction& c = high.result.conduction[0];
    const std::vector<ContactEpisode>& eps = high.result.episodes;
    ASSERT_GT(eps.size(), 3u);
    ASSERT_EQ(c.stretches.size(), eps.size());
    int openings = 0;
    double smallest = INFINITY;
    for (std::size_t i = 0; i < eps.size(); ++i) {
        SCOPED_TRACE("episode " + std::to_string(i));
        const ConductionStretch& s = c.stretches[i];
        const double t_c = eps[i].t_off - eps[i].t_on;
        EXPECT_GE(s.t_on, eps[i].t_on);
        EXPECT_LT(s.t_on - eps[i].t_on, 1e-3 * t_c);
        EXPECT_LE(s.t_off, eps[i].t_off);
        EXPECT_LT(eps[i].t_off - s.t_off, 1e-3 * t_c);
        EXPECT_EQ(s.on_at_end, eps[i].closed_at_end);
        if (!eps[i].closed_at_end) ++openings;
        smallest = std::min(smallest, s.min_resistance);
    }
    const std::optional<ElectricalLedger> l = electrical_ledger(c);
    ASSERT_TRUE(l);
    EXPECT_EQ(l->bounces, openings);
    ASSERT_TRUE(eps.back().closed_at_end);
    ASSERT_TRUE(l->settle_time);
    EXPECT_EQ(*l->settle_time, c.stretches.back().t_on);
    for (std::size_t i = 0; i + 1 < l->openings.size(); ++i) {
        EXPECT_NEAR(*l->openings[i].duration, eps[i + 1].t_on - eps[i].t_off, 1e-3 * (eps[i + 1].t_on - eps[i].t_off));
        EXPECT_EQ(l->openings[i].closure_min_resistance, c.stretches[i].min_resistance);
    }
    EXPECT_TRUE(std::isfinite(c.end_resistance));
    EXPECT_LT(c.end_resistance, 1e6);

    const SimulationRun low = run_quiet(switch_case(0.999 * smallest));
    const std::optional<ElectricalLedger> never = electrical_ledger(low.result.conduction[0]);
    ASSERT_TRUE(never);
    EXPECT_EQ(never->bounces, 0);
    EXPECT_FALSE(never->first_closure);
    EXPECT_FALSE(never->settle_time);
    EXPECT_EQ(low.result.episodes.size(), eps.size());  // the threshold changes nothing mechanical
}

// The ledger is found on the solver's steps and events: a tenfold coarser output step gives the
// same stretches, bit for bit, while the history-based time in the summary moves with the samples.
TEST(ElectricalBounce, DoesNotDependOnTheOutputStep) {
    Case fine = switch_case(0.5);
    Case coarse = fine;
    coarse.solver.output_step = 10.0 * run_quiet(fine).result.history.t[1];
    const SimulationRun a = run_quiet(fine), b = run_quiet(coarse);
    ASSERT_NE(a.result.history.t.size(), b.result.history.t.size());
    const std::vector<ConductionStretch>& sa = a.result.conduction[0].stretches;
    const std::vector<ConductionStretch>& sb = b.result.conduction[0].stretches;
    ASSERT_EQ(sa.size(), sb.size());
    ASSERT_GT(sa.size(), 1u);
    for (std::size_t i = 0; i < sa.size(); ++i) {
        EXPECT_EQ(sa[i].t_on, sb[i].t_on);
        EXPECT_EQ(sa[i].t_off, sb[i].t_off);
        EXPECT_EQ(sa[i].min_resistance, sb[i].min_resistance);
    }
    // The summary: the ledger beside the sampled values, and within one output step of them.
    const nlohmann::json j = transient_summary_json(fine, a.built, a.result, a.summary)["contact_resistance"][0];
    const std::optional<ElectricalLedger> l = electrical_ledger(a.result.conduction[0]);
    EXPECT_EQ(j["electrical_bounces"].get<int>(), l->bounces);
    EXPECT_EQ(j["settle_time_s"].get<double>(), *l->settle_time);
    EXPECT_EQ(j["openings"].size(), l->openings.size());
    EXPECT_EQ(j["openings"][0]["closure_min_resistance_ohm"].get<double>(), sa[0].min_resistance);
    const double step = a.result.history.t[1];
    EXPECT_LE(j["below_r_on_from_s"].get<double>() - *l->settle_time, step);
    EXPECT_GE(j["below_r_on_from_s"].get<double>(), *l->settle_time);
}

// Every sample of the history agrees with the stretches: below r_on inside one, at or above it (or
// open) outside, but for samples within 1e-13 s of a stretch's end; the switch example's closures
// sag and rise above r_on while closed, so this covers the crossings inside a closure too.
TEST(ElectricalBounce, StretchesHoldEverySampleBelowTheThreshold) {
    // At rtol 1e-3 CVODE's steps are long enough that one closure sags above 0.5 ohm and back within
    // a single step (34.03 to 34.28 us, about 15 samples above r_on): the dip between two returns.
    for (const auto& [r_on, rtol] : {std::pair{0.5, 0.0}, {0.2, 0.0}, {0.12, 0.0}, {0.5, 1e-3}}) {
        SCOPED_TRACE("r_on " + std::to_string(r_on) + ", rtol " + std::to_string(rtol));
        Case c = switch_case(r_on);
        if (rtol > 0.0) c.solver.rtol = rtol;
        const SimulationRun run = run_quiet(c);
        const std::vector<ResistanceSeries> series = contact_resistances(run.built.model, run.result);
        ASSERT_EQ(series.size(), 1u);
        const std::vector<ConductionStretch>& st = run.result.conduction[0].stretches;
        const TimeHistory& h = run.result.history;
        std::size_t inside = 0, mismatched = 0;
        for (std::size_t i = 0; i < h.t.size(); ++i) {
            bool in = false, near_end = false;
            for (const ConductionStretch& s : st) {
                in = in || (h.t[i] >= s.t_on && h.t[i] <= s.t_off);
                near_end = near_end || std::abs(h.t[i] - s.t_on) < 1e-13 || std::abs(h.t[i] - s.t_off) < 1e-13;
            }
            inside += in ? 1 : 0;
            if (in != (series[0].ohm[i] < r_on) && !near_end) ++mismatched;
        }
        EXPECT_EQ(mismatched, 0u);
        EXPECT_GT(inside, 50u);
    }
}

// The sweep's columns: the ledger of the first resistive support, empty without a resistance model.
TEST(ElectricalBounce, SweepColumns) {
    const std::vector<SweepColumn> cols = sweep_result_columns(SweepAnalysis::simulate, 0);
    std::size_t n = 0;  // one past resistance_end_ohm
    while (n < cols.size() && cols[n].name != "electrical_bounces") ++n;
    n += 3;
    ASSERT_LE(n, cols.size());
    EXPECT_EQ(cols[n - 3].name, "electrical_bounces");
    EXPECT_EQ(cols[n - 2].name, "settle_time_s");
    EXPECT_EQ(cols[n - 1].name, "resistance_end_ohm");
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    const SimulationRun run = run_simulation(switch_case(0.5), o);
    const std::vector<SweepCell> cells = simulate_cells(run);
    ASSERT_EQ(cells.size(), cols.size());
    const std::optional<ElectricalLedger> l = electrical_ledger(run.result.conduction[0]);
    EXPECT_EQ(std::get<std::int64_t>(cells[n - 3]), l->bounces);
    EXPECT_EQ(std::get<double>(cells[n - 2]), *l->settle_time);
    EXPECT_EQ(std::get<double>(cells[n - 1]), run.result.conduction[0].end_resistance);

    Case plain = read_case_file(test::source_path("examples/paper/free_impact_tip.toml"));
    const std::vector<SweepCell> none = simulate_cells(run_simulation(plain, o));
    for (std::size_t k = n - 3; k < n; ++k) EXPECT_TRUE(std::holds_alternative<std::monostate>(none[k])) << k;
}

// --r-on sets the threshold of every resistive support; a bad value or a case without a resistance
// model is one line, exit 2, nothing written.
TEST(ElectricalBounce, CommandOption) {
    const std::string hertz = test::source_path("examples/switch/cantilever_switch_hertz.toml");
    const test::CommandResult ok = test::run_vibroimpact({"simulate", hertz, "--json", "--r-on", "1e6"});
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    const nlohmann::json summary = nlohmann::json::parse(ok.out);
    const nlohmann::json& j = summary["contact_resistance"][0];
    EXPECT_EQ(j["r_on_ohm"].get<double>(), 1e6);
    int openings = 0;
    for (const nlohmann::json& e : summary["episodes"]) openings += e["closed_at_end"].get<bool>() ? 0 : 1;
    EXPECT_EQ(j["electrical_bounces"].get<int>(), openings);

    const std::filesystem::path out = std::filesystem::temp_directory_path() / "vi_r_on_bad";
    std::filesystem::remove_all(out);
    const std::string paper = test::source_path("examples/paper/free_impact_tip.toml");
    const struct {
        std::string file, value, message;
    } bad[] = {
        {hertz, "abc", "--r-on \"abc\": "},
        {hertz, "-1", "--r-on \"-1\": the threshold must be above 0 ohm"},
        {hertz, "0", "--r-on \"0\": the threshold must be above 0 ohm"},
        {hertz, "1 V", "--r-on \"1 V\": "},
        {paper, "0.5", "--r-on: no support of "},
    };
    for (const auto& b : bad) {
        SCOPED_TRACE(b.value);
        const test::CommandResult r = test::run_vibroimpact({"simulate", b.file, "--r-on", b.value, "--out", out.string()});
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find("vibroimpact: error: " + b.message), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

}  // namespace electrical_test
}  // namespace vi
