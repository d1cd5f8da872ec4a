#pragma once
// The stiction check (study/stiction/stiction.hpp) as JSON, a terminal summary and CSV.

#include <nlohmann/json.hpp>
#include <string>

#include "io/output_files.hpp"
#include "study/stiction/stiction.hpp"

namespace vi {

// {"supports": [{support, law, restoring_force_n, pull_off_force_n, verdict, ...}], "detached": [...], "note"}
nlohmann::json stiction_json(const StictionResult& r);

// One paragraph per adhesive support, then the detached lengths.
std::string stiction_text(const StictionResult& r);

// stiction.json, stiction.csv (one row per adhesive support, its detached length where defined).
OutputFiles stiction_files(const StictionResult& r);

}  // namespace vi
