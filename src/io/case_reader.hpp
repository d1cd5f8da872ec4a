#pragma once
// Reads a TOML case file into a checked Case; every error names the file, the line and the key.

#include <string>

#include "model/input_error.hpp"
#include "model/case.hpp"

namespace vi {

// Reads and checks the case at path. Throws InputError("FILE:LINE: KEY: reason") on the first
// problem: unreadable file, TOML syntax, unknown or missing key, wrong type, bad unit, or any
// problem reported by check_case.
Case read_case_file(const std::string& path);

// Same, from text already in memory; source_name stands for the file in messages.
Case read_case_text(const std::string& text, const std::string& source_name);

// An error "KEY: reason" found after reading (building or running the case), placed in the file:
// "FILE:LINE: KEY: reason" with the line of the key (or of its table). Unchanged for cases built
// in code or messages that do not start with a key.
InputError locate_in_case(const Case& c, const InputError& e);

}  // namespace vi
