#pragma once
// Column names of the CSV files: every name ends in its unit ("t_s", "tip_m", "force_un") or is a
// dimensionless name ("z_max", "tau", "ratio_2", "impacts"); docs/architecture.md, "Output files".

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vi {

// A column name split at its unit ending: "tip_velocity_m_s" -> {"tip_velocity", "m/s", "_m_s"};
// a name without a unit ending keeps it whole, with unit and suffix empty.
struct CsvColumnUnit {
    std::string stem;
    std::string unit;    // as printed: "m/s", "µm", "kg/m³", "x/l"
    std::string suffix;  // as in the name: "_m_s", "_um", "_kg_m3", "_over_l"
};
CsvColumnUnit csv_column_unit(std::string_view name);

// The name ending of a unit as the case paths give it (sweep/case_paths.hpp): "m" -> "_m",
// "N s/m" -> "_n_s_m", "kg/m^3" -> "_kg_m3", "x/l" -> "_over_l", "-" -> "" (dimensionless: the
// name alone). Throws std::invalid_argument for a unit it does not know.
std::string csv_unit_suffix(std::string_view unit);

// True when `name` follows the rule: the part after its last '.' (a case path's field, or the whole
// name) ends in a unit suffix of csv_column_unit after a non-empty stem, or is, or ends in "_" and,
// a dimensionless name (digits standing for any number: "ratio_#", "tau#", "Y_#_#", "impacts",
// "z_max", "status", ...; the list is in csv_names.cpp and docs/architecture.md).
bool csv_column_name_ok(std::string_view name);

// stem + k + suffix for k = 1 .. count: numbered columns ("f", 3, "_hz" -> f1_hz, f2_hz, f3_hz).
std::vector<std::string> numbered_columns(std::string_view stem, std::size_t count, std::string_view suffix);

}  // namespace vi
