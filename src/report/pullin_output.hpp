#pragma once
// Pull-in results (statics/pullin.hpp) as JSON, a terminal summary and CSV files.

#include <nlohmann/json.hpp>
#include <string>

#include "statics/pullin.hpp"
#include "impacts/dynamic_pullin.hpp"
#include "io/output_files.hpp"

namespace vi {

// {"pullin": {...} or null, "touchdown", "release_voltage_V", "end", "branch_points", ...}
nlohmann::json pullin_json(const PullinResult& r);

// A few lines for a terminal: V_PI, travel at pull-in, touch-down, release, why the branch ends.
std::string pullin_text(const PullinResult& r);

// pullin.json, pullin_branch.csv (the equilibria), pullin_frequencies.csv (f against V).
OutputFiles pullin_files(const PullinResult& r);

// {"voltage_V", "ratio_to_static", "lower_V", "upper_V", "criterion", "horizon_s", "trials": [...]}.
nlohmann::json dynamic_pullin_json(const DynamicPullinResult& r);

// "Dynamic pull-in V_DPI = ... V (= ... of static)" and the bracket, one line each.
// Which model the bracket holds for, in one sentence.
std::string dynamic_pullin_model_text(const DynamicPullinResult& r);
std::string dynamic_pullin_text(const DynamicPullinResult& r);

}  // namespace vi
