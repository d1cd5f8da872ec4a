#pragma once
// What the fuzz tests require of one run of the command line: it ended within its limit with exit 0,
// 1 or 2; exit 2 with one error line naming file, line and key, and nothing written; exit 1 with one
// failure line after any warnings, and nothing written; exit 0 with its files; no sanitizer report.

#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace vi::test {

// What one run was asked to do.
struct FuzzRun {
    std::string case_dir;       // the folder holding the case file and any file beside it
    std::string case_path;      // the case file, as given on the command line
    std::string out_dir;        // --out, which must not exist after exit 1 or 2
    std::string expected_file;  // a file exit 0 must have written, e.g. out_dir + "/summary.json"
    std::string limit;          // the run's limit, in words, for the message of a run killed by it
};

// The environment variable `name` as a whole number >= 0, or fallback when unset or not one.
long env_number(const char* name, long fallback);

// The lines of text, without their newlines.
std::vector<std::string> lines_of(const std::string& text);

// True when message (after "vibroimpact: error: ") names a file in case_dir with a line, and, for
// the case file itself, a key or "TOML syntax": "DIR/case.toml:12: electrodes[0].gap: ...", perhaps
// after the option that derived the value ("--horizon (default ...): the case's DIR/case.toml:...").
bool names_file_line_and_key(const std::string& message, const FuzzRun& run);

// What is wrong with one run; empty when it ended as a run must.
std::string run_defect(const CommandResult& r, const FuzzRun& run);

}  // namespace vi::test
