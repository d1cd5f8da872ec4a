#pragma once
// One [[electrodes]] entry of a case file: span, side, gap, dielectric, fringing and the voltage
// waveform (docs/electrostatics.md §1). Part of the case reader (io/case_reader.cpp).

#include <optional>
#include <string>
#include <vector>

#include "io/toml_fields.hpp"
#include "model/case.hpp"
#include "model/case_checks.hpp"

namespace vi {

// Reads the entry at `path` ("electrodes[0]"). Problems with the text go to log, problems with
// values to value_problems; a waveform = "table" leaves its CSV file name (as written) in table_file.
Electrode read_electrode(const toml::table& t, const std::string& path, tomlio::Position at, tomlio::ReadLog& log,
                         std::vector<CaseProblem>& value_problems, std::optional<std::string>& table_file);

}  // namespace vi
