#pragma once
// What the fuzz tests require of one run of the command line: it ended within its limit with exit 0,
// 1 or 2; exit 2 with one error line naming file, line and key, and nothing written; exit 1 with one
// failure line after any warnings, and nothing written; exit 0 with its files; no sanitizer report.

#include <cstdint>
#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace vi::test {

// The fuzz tests' fixed sequence, and the most mutants a timed run (VI_FUZZ_SECONDS) draws.
inline constexpr std::uint64_t kFuzzSeed = 20250611;
inline constexpr long kMaxFuzzMutants = 10000000;
// Mutants of a run by count: the first 300 of the same sequence in the short run (sanitizer builds:
// tests/CMakeLists.txt, VI_SHORT_TESTS), 3000 in Release.
#if VI_SHORT_TESTS
inline constexpr long kFuzzMutants = 300;
#else
inline constexpr long kFuzzMutants = 3000;
#endif
// The CPU seconds one run may take before it counts as a hang (a defect). Most runs end within a
// few, but a bounded run may take longer: a CVODE run whose pace would need a little more than its
// 10^6 steps spends half of them before its pace refuses it (a mutant of bridge_relay with an air
// film: 9 s of CPU on one 2-core machine, 25-28 s on a slower one). The sanitizers slow a run 3 to 10
// times, but their short run draws the first 300 mutants only.
inline constexpr double kFuzzLimitSeconds = 60.0;

// What a fuzz run is asked for, from the environment: VI_FUZZ_SEED=N (another sequence),
// VI_FUZZ_MUTANTS=N (count), VI_FUZZ_SECONDS=S (draw until S seconds have passed instead, at most
// kMaxFuzzMutants), VI_FUZZ_ONLY=I (mutant I alone, saved), VI_FUZZ_VERBOSE=1 (one line per run).
struct FuzzSettings {
    std::uint64_t seed = kFuzzSeed;
    long seconds = 0;           // 0: run `mutants`
    long mutants = kFuzzMutants;
    long only = -1;             // -1: every mutant
    bool verbose = false;
    [[nodiscard]] long first() const { return only >= 0 ? only : 0; }
    [[nodiscard]] long count() const { return only >= 0 ? 1 : mutants; }
    // The line that opens a run's output, e.g. "seed 20250611, 3000 mutants".
    [[nodiscard]] std::string describe() const;
};
FuzzSettings fuzz_settings();

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
