#pragma once
// Whole files as text for tests: what a command wrote, and case files a test writes.

#include <string>

namespace vi::test {

// The whole file (binary, as is); empty when it cannot be read.
std::string read_text(const std::string& path);

// Writes text as the whole file (binary, as is).
void write_text(const std::string& path, const std::string& text);

}  // namespace vi::test
