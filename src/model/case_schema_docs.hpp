#pragma once
// The key tables of docs/case-files.md, generated from the schema (model/case_schema.hpp).

#include <string>
#include <vector>

#include "model/case_schema.hpp"

namespace vi {

// The Markdown table of section s: one row per key with its meaning, type or unit, default, range
// and the condition it needs ("only with").
std::string case_key_table(const SectionSpec& s);

// page with the text between every "<!-- case-keys:NAME -->" line and the next
// "<!-- /case-keys:NAME -->" line replaced by the table of section NAME ("top-level" for the top
// level) of schema, and the text between "<!-- registered-sections -->" and
// "<!-- /registered-sections -->" by every registered section that has no block of its own: its
// heading, paragraph and table, in the schema's order (so a section a force family registers is
// documented without editing the page). Throws std::invalid_argument for an unknown section or a
// block without its end.
std::string with_case_key_tables(const std::string& page, const CaseSchema& schema);

// The sections of schema that the page shows neither in a block of their own nor, registered, in
// its block of registered sections.
std::vector<std::string> undocumented_sections(const std::string& page, const CaseSchema& schema);

}  // namespace vi
