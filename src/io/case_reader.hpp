#pragma once
// Reads a TOML case file into a checked Case; every error names the file, the line and the key.

#include <string>

#include "model/case.hpp"

namespace vi {

// Reads and checks the case at path. Throws InputError("FILE:LINE: KEY: reason") on the first
// problem: unreadable file, TOML syntax, unknown or missing key, wrong type, bad unit, or any
// problem reported by check_case.
Case read_case_file(const std::string& path);

// Same, from text already in memory; source_name stands for the file in messages.
Case read_case_text(const std::string& text, const std::string& source_name);

}  // namespace vi
