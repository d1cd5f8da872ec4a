// CVODE's flights in closed form (CvodeOptions::free_flight, dynamics/cvode/free_flight.hpp) against
// the same runs stepped through by CVODE: the paper's free impact on a Hertz dimple, where every
// flight is free, and the Hertz switch, whose electrode acts in flight so that nothing changes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "dynamics/cvode/cvode_solver.hpp"
#include "forces/hertz_contact.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace free_flight_test {

struct Runs {
    TransientResult closed, stepped;
    ImpactSummary closed_summary, stepped_summary;
};

Runs both(const Case& c) {
    const BuiltProblem b = build_transient_problem(c);
    const TransientOptions o = transient_options(c.solver);
    CvodeOptions co = cvode_options(c.solver);
    Runs r;
    co.free_flight = true;
    r.closed = solve_cvode(b.problem, o, co);
    co.free_flight = false;
    r.stepped = solve_cvode(b.problem, o, co);
    r.closed_summary = summarize_impacts(r.closed, impact_settings(c, b));
    r.stepped_summary = summarize_impacts(r.stepped, impact_settings(c, b));
    return r;
}

double total(const EnergyLedger& e) {
    return e.kinetic + e.strain + e.contact_spring + e.electrical + e.rayleigh_dissipated + e.contact_dissipated +
           e.film_dissipated - e.external_work;
}

TEST(FreeFlight, HertzFreeImpactAsSteppedThroughEveryFlight) {
    Case c = read_case_file(test::source_path("bench/cases/free_impact_hertz.toml"));
    c.solver.reduced_modes = 10;
    const Runs r = both(c);
    EXPECT_GT(r.closed.stats.free_flights, 30);
    EXPECT_EQ(r.stepped.stats.free_flights, 0);
    EXPECT_LT(r.closed.stats.steps, r.stepped.stats.steps / 2);
    const double t_end = c.solver.horizon;
    ASSERT_EQ(r.closed.episodes.size(), r.stepped.episodes.size());
    double dt = 0.0, dv = 0.0, df = 0.0, de = 0.0;
    for (std::size_t k = 0; k < r.closed.episodes.size(); ++k) {
        const ContactEpisode &a = r.closed.episodes[k], &b = r.stepped.episodes[k];
        dt = std::max({dt, std::abs(a.t_on - b.t_on) / t_end, std::abs(a.t_off - b.t_off) / t_end});
        dv = std::max({dv, std::abs(a.v_in - b.v_in) / std::abs(r.stepped.episodes[0].v_in),
                       std::abs(a.v_out - b.v_out) / std::abs(r.stepped.episodes[0].v_in)});
        df = std::max(df, std::abs(a.peak_force - b.peak_force) / r.stepped.episodes[0].peak_force);
        de = std::max(de, std::abs(a.contact_energy - b.contact_energy) / r.stepped.initial_energy.strain);
    }
    // Observed: 5e-8, 2e-8, 2e-8, 8e-12 (CVODE at rtol 1e-10 against itself with another path).
    EXPECT_LT(dt, 1e-6);
    EXPECT_LT(dv, 1e-6);
    EXPECT_LT(df, 1e-6);
    EXPECT_LT(de, 1e-9);
    const ImpactSummary &s = r.closed_summary, &z = r.stepped_summary;
    ASSERT_EQ(s.impacts.size(), z.impacts.size());
    for (std::size_t k = 0; k < s.impacts.size(); ++k) {
        EXPECT_EQ(s.impacts[k].episodes, z.impacts[k].episodes);  // the bounces
        // The restitution, of the impacts above 1 % of the first one's speed: the last micro-impacts'
        // speeds share the same absolute error (dv), a larger part of theirs.
        if (std::abs(z.impacts[k].v_in) < 0.01 * std::abs(z.impacts[0].v_in)) continue;
        const double ea = s.impacts[k].v_out / s.impacts[k].v_in, eb = z.impacts[k].v_out / z.impacts[k].v_in;
        EXPECT_NEAR(ea, eb, 1e-6);
    }
    // The cycles to 1e-7 of the horizon (observed: 1.4e-8, the late cycles' 1e-12 s).
    ASSERT_EQ(s.T.size(), z.T.size());
    for (std::size_t k = 0; k < s.T.size(); ++k) EXPECT_NEAR(s.T[k], z.T[k], 1e-7 * t_end);
    ASSERT_TRUE(s.Tp && z.Tp);
    EXPECT_NEAR(*s.Tp, *z.Tp, 1e-7 * t_end);
    ASSERT_TRUE(s.y_max && z.y_max);
    EXPECT_NEAR(*s.y_max, *z.y_max, 1e-8 * std::abs(*z.y_max));
    // The ledger closes both ways (observed 3e-10 and 6e-10 of the initial energy), and its terms agree.
    const double e0 = r.stepped.initial_energy.strain;
    const EnergyLedger &ea = r.closed.final_energy, &eb = r.stepped.final_energy;
    EXPECT_LT(std::abs(total(ea) - total(r.closed.initial_energy)) / e0, 1e-8);
    EXPECT_LT(std::abs(total(eb) - total(r.stepped.initial_energy)) / e0, 1e-8);
    EXPECT_NEAR(ea.rayleigh_dissipated, eb.rayleigh_dissipated, 1e-8 * e0);
    EXPECT_NEAR(ea.contact_dissipated, eb.contact_dissipated, 1e-8 * e0);
    EXPECT_NEAR(ea.kinetic + ea.strain, eb.kinetic + eb.strain, 1e-8 * e0);
}

// The switch's electrode pulls in flight too: no flight is free, and the run is CVODE's stepped one.
TEST(FreeFlight, SwitchWithAnElectrodeStepsEveryFlight) {
    Case c = read_case_file(test::source_path("examples/switch/cantilever_switch_hertz.toml"));
    c.solver.reduced_modes = 10;
    c.solver.horizon = 15e-6;
    const Runs r = both(c);
    EXPECT_EQ(r.closed.stats.free_flights, 0);
    ASSERT_FALSE(r.closed.episodes.empty());
    ASSERT_EQ(r.closed.episodes.size(), r.stepped.episodes.size());
    for (std::size_t k = 0; k < r.closed.episodes.size(); ++k) {
        EXPECT_EQ(r.closed.episodes[k].t_on, r.stepped.episodes[k].t_on);
        EXPECT_EQ(r.closed.episodes[k].t_off, r.stepped.episodes[k].t_off);
    }
    EXPECT_EQ(r.closed.stats.steps, r.stepped.stats.steps);
}

// The open Hertz contact's free mode is its switching function, part by part, where it acts not at
// all; closed, it has none.
TEST(FreeFlight, OpenHertzContactsFreeModeIsItsSwitchingFunction) {
    for (const double sign : {1.0, -1.0}) {
        const HertzContact h("supports[0]", 0, sign, 0.3e-6, 0.0, 9e7, 0.4, 2e-6);
        ASSERT_FALSE(h.free_mode(1));
        const std::optional<FreeMode> m = h.free_mode(0);
        ASSERT_TRUE(m);
        for (const double q : {-1e-6, 0.2e-6, 0.3e-6, 0.5e-6}) {
            for (const double v : {-3.0, -1.0, 0.0, 2.5}) {
                const ElementState st{0.0, &q, &v, nullptr};
                double smallest = std::numeric_limits<double>::infinity();
                for (const LinearPart& p : m->parts) smallest = std::min(smallest, p.wq[0] * q + p.wv[0] * v + p.offset);
                EXPECT_NEAR(smallest, h.switching_function(st, 0), 1e-12 * std::max(1.0, std::abs(smallest)));
                double f = 0.0;
                h.add_force(st, 0, &f);
                EXPECT_EQ(f, 0.0);
                EXPECT_EQ(h.stored_energy(st, 0), 0.0);
                EXPECT_EQ(h.dissipated_power(st, 0), 0.0);
            }
        }
    }
}

}  // namespace free_flight_test
}  // namespace vi
