#pragma once
// The cycles study (study/cycles/cycles.hpp) as CSV, JSON and a terminal summary.

#include <nlohmann/json.hpp>
#include <string>

#include "io/csv_writer.hpp"
#include "io/output_files.hpp"
#include "study/cycles/cycles.hpp"

namespace vi {

// One row per cycle: cycle, t_start_s, closing_time_s, bounces, grouped_bounces, switching_state,
// impacts, contact_energy_j, peak_force_n, peak_pressure_pa, yield_impacts, electrical_bounces,
// wear_volume_m3, cumulative_wear_m3 (a missing value where the run has none).
CsvTable cycles_csv(const CyclesResult& r);

// {"cycles", "period_s", "total_contact_energy_j", "total_wear_volume_m3", "yield_impacts",
//  "trend": {"contact_energy_j", "bounces", "peak_force_n"}: {slope_per_cycle, intercept, first, last},
//  "per_cycle": [...the CSV's rows...], "solver": {method, steps}}.
nlohmann::json cycles_json(const CyclesResult& r);

// A few lines: the totals, the first and last cycles, the trends.
std::string cycles_text(const CyclesResult& r);

// cycles.csv and cycles.json.
OutputFiles cycles_files(const CyclesResult& r);

}  // namespace vi
