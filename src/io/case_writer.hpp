#pragma once
// A Case written back as a case file (TOML text) or as the same content in JSON, from the schema:
// every key in effect with its value (defaults filled in), in SI, in the file's section and array
// layout. Read back, either gives the same Case (bit for bit in its numbers).

#include <string>

#include <nlohmann/json.hpp>

#include "model/case.hpp"

namespace vi {

// The case as TOML text: the top-level keys, then one [table] or [[array]] entry per section entry,
// each key in effect on its own line with its SI unit in a comment. A table file is named by its
// absolute path (resolved against the folder of the case file it was read from), so the text reads
// the same rows from anywhere.
std::string case_to_toml(const Case& c);

// The same content as JSON: tables as objects, arrays of tables as arrays of objects.
nlohmann::json case_to_json(const Case& c);

}  // namespace vi
