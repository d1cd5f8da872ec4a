// The cycles study (study/cycles/cycles.hpp): the drive repeated, the first cycle against a single
// run of one period, the cycles' sums against the whole run, the wear estimate K E / H, the trend's
// least-squares line, the command's files and its refusals.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "io/csv_names.hpp"
#include "model/input_error.hpp"
#include "study/cycles/cycles.hpp"
#include "study/cycles/cycles_output.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace cycles_test {

const char* const kExample = "examples/switch/cantilever_switch_hertz_cycles.toml";

TEST(Cycles, TheDriveIsTheWaveformRepeatedEveryPeriod) {
    const Case c = read_case_file(test::source_path(kExample));
    const Case r = cycled_case(c, {3, 100e-6});
    EXPECT_DOUBLE_EQ(r.solver.horizon, 300e-6);
    const TimeFunction& g = c.electrodes[0].time;
    const TimeFunction& h = r.electrodes[0].time;
    for (const double t : {0.1e-6, 15e-6, 30.3e-6, 60e-6, 99e-6}) {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(h(t + k * 100e-6), g(t), 1e-12) << t << " " << k;
    }
    EXPECT_EQ(h(250e-6), 0.0);
}

TEST(Cycles, RefusesWhatDoesNotRepeat) {
    Case c = read_case_file(test::source_path(kExample));
    EXPECT_THROW((void)cycled_case(c, {0, 100e-6}), InputError);
    EXPECT_THROW((void)cycled_case(c, {kMaxCycles + 1, 100e-6}), InputError);
    try {
        (void)cycled_case(c, {2, 20e-6});  // the pulse lasts 30.4 us
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("electrodes[0].waveform: the drive must lie within one period", 0), 0u) << e.what();
    }
    c.electrodes[0].waveform.kind = Waveform::Kind::step;
    try {
        (void)cycled_case(c, {2, 100e-6});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("electrodes[0].waveform: \"step\" stays on", 0), 0u) << e.what();
    }
}

// Cycle 0 of three is the single run of one period (the same drive up to then; CVODE's steps near
// the period's end may differ, so times agree to its tolerance); the cycles' sums are the whole
// run's; the wear is K E / H of each cycle's contact energy.
TEST(Cycles, FirstCycleIsTheSingleRunAndTheSumsAreTheWholeRuns) {
    const Case c = read_case_file(test::source_path(kExample));
    const CyclesResult r = run_cycles(c, {3, 0.0});
    ASSERT_EQ(r.cycles.size(), 3u);
    EXPECT_DOUBLE_EQ(r.settings.period, 100e-6);
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    const SimulationRun one = run_simulation(c, o);
    ASSERT_TRUE(one.switching && one.switching->closing_time);
    const CycleRecord& first = r.cycles[0];
    ASSERT_TRUE(first.switching.closing_time);
    EXPECT_NEAR(*first.switching.closing_time, *one.switching->closing_time, 1e-6 * *one.switching->closing_time);
    EXPECT_EQ(first.switching.bounces, one.switching->bounces);
    EXPECT_EQ(first.switching.state, one.switching->state);
    const double e1 = contact_damage(one.summary.impacts).contact_energy;
    EXPECT_NEAR(first.damage.contact_energy, e1, 1e-5 * e1);
    double sum = 0.0, wear = 0.0;
    const double k_over_h = 1e-4 / 1.2e9;
    for (const CycleRecord& x : r.cycles) {
        EXPECT_GT(x.switching.bounces, 0);
        EXPECT_GT(x.damage.contact_energy, 0.0);
        EXPECT_NEAR(x.wear_volume, k_over_h * x.damage.contact_energy, 1e-12 * x.wear_volume);
        sum += x.damage.contact_energy;
        wear += x.wear_volume;
    }
    EXPECT_NEAR(r.total_contact_energy, sum, 1e-12 * sum);
    EXPECT_NEAR(r.total_wear_volume, wear, 1e-12 * wear);
    EXPECT_TRUE(r.wear);
    EXPECT_TRUE(r.yield_known);
}

// The CSV's columns follow the project's naming rule (the unit in the name, io/csv_names.hpp).
TEST(Cycles, ColumnNamesCarryTheirUnits) {
    for (const std::string& name : cycles_csv(CyclesResult{}).header) EXPECT_TRUE(csv_column_name_ok(name)) << name;
}

TEST(Cycles, TrendIsTheLeastSquaresLine) {
    const CycleTrend t = cycle_trend({1.0, 3.0, 5.0, 7.0});
    EXPECT_NEAR(t.slope, 2.0, 1e-14);
    EXPECT_NEAR(t.intercept, 1.0, 1e-14);
    EXPECT_EQ(t.first, 1.0);
    EXPECT_EQ(t.last, 7.0);
    const CycleTrend flat = cycle_trend({4.0});
    EXPECT_EQ(flat.slope, 0.0);
    EXPECT_EQ(flat.intercept, 4.0);
}

TEST(Cycles, CommandWritesItsFilesAndRefusesBadCounts) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "vi_cycles_cmd";
    std::filesystem::remove_all(dir);
    const std::string example = test::source_path(kExample);
    const test::CommandResult ok =
        test::run_vibroimpact({"cycles", example, "--cycles", "2", "--out", dir.string(), "--progress", "lines",
                               "--progress-interval", "0"});
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_NE(ok.out.find("2 cycles of 100 us"), std::string::npos) << ok.out;
    EXPECT_NE(ok.err.find("cycles"), std::string::npos) << ok.err;  // progress lines on a pipe
    std::ifstream json_file(dir / "cycles.json");
    const nlohmann::json j = nlohmann::json::parse(json_file);
    EXPECT_EQ(j.at("per_cycle").size(), 2u);
    EXPECT_TRUE(std::filesystem::exists(dir / "cycles.csv"));
    std::filesystem::remove_all(dir);
    for (const std::string n : {"0", "100001", "-3", "1e9", "2.5", "many"}) {
        const test::CommandResult bad = test::run_vibroimpact({"cycles", example, "--cycles", n, "--out", dir.string()});
        EXPECT_EQ(bad.exit_code, 2) << n << bad.err;
        EXPECT_NE(bad.err.find("must be a whole number from 1 to 100000 (the most one study runs)"), std::string::npos)
            << bad.err;
        EXPECT_FALSE(std::filesystem::exists(dir));
    }
    const test::CommandResult short_period =
        test::run_vibroimpact({"cycles", example, "--cycles", "2", "--period", "20 us", "--out", dir.string()});
    EXPECT_EQ(short_period.exit_code, 2) << short_period.err;
    EXPECT_NE(short_period.err.find("cantilever_switch_hertz_cycles.toml:"), std::string::npos) << short_period.err;
    EXPECT_NE(short_period.err.find("electrodes[0].waveform: the drive must lie within one period"), std::string::npos)
        << short_period.err;
    EXPECT_FALSE(std::filesystem::exists(dir));
}

}  // namespace cycles_test
}  // namespace vi
