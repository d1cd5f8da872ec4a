// A simulate sweep's per-support columns (sweep/columns.hpp): every resistive support of the case
// has its electrical ledger and damage columns, named by its index, and the first one's agree with
// the columns of the first resistive support.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "impacts/electrical_ledger.hpp"
#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "support/run_command.hpp"
#include "sweep/columns.hpp"

namespace vi {
namespace support_columns_test {

SweepCell cell(const std::vector<SweepColumn>& cols, const std::vector<SweepCell>& cells, const std::string& name) {
    for (std::size_t i = 0; i < cols.size(); ++i) {
        if (cols[i].name == name) return cells.at(i);
    }
    ADD_FAILURE() << "no column " << name;
    return {};
}

// The Hertz switch with a second gold dimple under x/l = 0.9, 1.33 um below the beam: the beam lands
// on both, each with its own resistance and threshold.
TEST(SweepSupportColumns, EveryResistiveSupportHasItsOwnColumns) {
    Case c = read_case_file(test::source_path("examples/switch/cantilever_switch_hertz.toml"));
    c.solver.horizon = 30e-6;
    Support second = c.supports[0];
    second.position = 0.9;
    second.surface = -1.33e-6;
    second.params.numbers["r_on"] = 0.8;
    second.params.numbers["yield_strength"] = 300e6;
    c.supports.push_back(second);
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    const SimulationRun run = run_simulation(c, o);
    const std::vector<SweepColumn> cols = sweep_result_columns(SweepAnalysis::simulate, 0, 2);
    const std::vector<SweepCell> cells = simulate_cells(run, 2);
    ASSERT_EQ(cols.size(), cells.size());
    ASSERT_EQ(run.result.conduction.size(), 2u);
    for (int k = 0; k < 2; ++k) {
        SCOPED_TRACE(k);
        const std::string p = "support" + std::to_string(k) + "_";
        int contact = -1;
        for (std::size_t j = 0; j < run.built.model.contacts.size(); ++j) {
            if (run.built.model.contacts[j].name == "supports[" + std::to_string(k) + "]") contact = static_cast<int>(j);
        }
        const ContactConduction* own = nullptr;
        for (const ContactConduction& x : run.result.conduction) {
            if (x.contact == contact) own = &x;
        }
        ASSERT_NE(own, nullptr);
        const std::optional<ElectricalLedger> l = electrical_ledger(*own);
        ASSERT_TRUE(l.has_value());
        EXPECT_GT(l->bounces, 0);
        EXPECT_EQ(std::get<std::int64_t>(cell(cols, cells, p + "electrical_bounces")), l->bounces);
        double energy = 0.0;
        int impacts = 0;
        for (const Impact& im : run.summary.impacts) {
            if (im.support != contact) continue;
            energy += im.contact_energy;
            ++impacts;
        }
        EXPECT_GT(impacts, 0);
        EXPECT_DOUBLE_EQ(std::get<double>(cell(cols, cells, p + "contact_energy_j")), energy);
        EXPECT_GT(std::get<double>(cell(cols, cells, p + "peak_pressure_pa")), 0.0);
    }
    // Only the second has a yield strength; the first's yield column is empty.
    EXPECT_TRUE(std::holds_alternative<std::monostate>(cell(cols, cells, "support0_yield_impacts")));
    EXPECT_TRUE(std::holds_alternative<std::int64_t>(cell(cols, cells, "support1_yield_impacts")));
    EXPECT_EQ(std::get<std::int64_t>(cell(cols, cells, "support0_electrical_bounces")),
              std::get<std::int64_t>(cell(cols, cells, "electrical_bounces")));
    // The sums over the supports.
    EXPECT_NEAR(std::get<double>(cell(cols, cells, "contact_energy_j")),
                std::get<double>(cell(cols, cells, "support0_contact_energy_j")) +
                    std::get<double>(cell(cols, cells, "support1_contact_energy_j")),
                1e-12 * std::get<double>(cell(cols, cells, "contact_energy_j")));
}

}  // namespace support_columns_test
}  // namespace vi
