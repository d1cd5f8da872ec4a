#pragma once
// What `--json` prints for a command whose result is a table: the table's CSV as JSON.

#include <nlohmann/json.hpp>
#include <string>

namespace vi::cli {

// {"columns": [names], "rows": [[cells]]}: a cell that reads as a number is a number, the missing
// marker (nan, or an empty cell) null, other text a string; an infinity is written as null (JSON has none).
nlohmann::json csv_as_json(const std::string& csv_text, const std::string& name);

// Prints j on stdout, indented, with a final newline.
void print_json(const nlohmann::json& j);

}  // namespace vi::cli
