#pragma once
// What `validate --json` prints: the sections of a generated Markdown document and their tables.

#include <nlohmann/json.hpp>
#include <string>

namespace vi::cli {

// {"title": the "# " heading, "sections": [{"number": N of a "## N. Title" heading (null when the
// heading has none), "title", "tables": [{"columns": [header cells], "rows": [[cells]]}]}]}.
// A cell that reads as a number is a number, "n/a" or an empty cell null, other text a string.
nlohmann::json markdown_tables_json(const std::string& markdown);

}  // namespace vi::cli
