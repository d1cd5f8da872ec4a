// Fuzz test of the command line: mutants of the example case files (values to
// extremes, units swapped, keys removed, duplicated, misspelled, wrong types, truncation, random
// bytes, extra tables; tests/support/case_mutator.*) each run `vibroimpact simulate MUTANT --out DIR`
// (every fourth `modes`) in a child process with a wall-clock limit. Every run must end inside the
// limit with exit 0, 1 or 2: exit 2 with one error line naming file, line and key and nothing
// written, exit 1 with one
// "vibroimpact: failure:" (or error) line and nothing written, exit 0 with its files; no signal, no
// sanitizer report. A failing mutant is saved for replay (the message says where).
//
// Deterministic: seed and count are fixed (printed). Longer runs: VI_FUZZ_MUTANTS=N (count),
// VI_FUZZ_SECONDS=S (run until S seconds have passed instead, at most 10^7 mutants), VI_FUZZ_SEED=N
// (another sequence), VI_FUZZ_ONLY=I (replay mutant I alone, and save it), VI_FUZZ_VERBOSE=1 (one line per
// mutant: its exit code and message, to review the messages).

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "support/case_mutator.hpp"
#include "support/fuzz_checks.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::Mutant;

const std::vector<std::string> kSources = {"examples/paper/free_impact_tip.toml",
                                           "examples/paper/free_impact_prestress.toml",
                                           "examples/paper/cantilever.toml"};

// A failing mutant saved where the message says, to replay with `vibroimpact COMMAND FILE`.
std::string save_finding(const Mutant& m, std::uint64_t seed, long index) {
    const fs::path dir = fs::temp_directory_path() / "vi_fuzz_findings";
    fs::create_directories(dir);
    const fs::path file = dir / ("seed" + std::to_string(seed) + "-mutant" + std::to_string(index) + ".toml");
    test::write_text(file.string(), m.text);
    return file.string();
}

TEST(FuzzCli, EveryMutantEndsInTimeWithExitZeroOneOrTwo) {
    const test::FuzzSettings f = test::fuzz_settings();
    const std::uint64_t seed = f.seed;
    const long only = f.only;
    std::printf("fuzz: %s, limit per run %.0f s of wall time\n", f.describe().c_str(), test::kFuzzLimitSeconds);

    std::vector<std::string> sources;
    for (const std::string& s : kSources) sources.push_back(test::read_text(test::source_path(s)));
    for (const std::string& s : sources) ASSERT_FALSE(s.empty());

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    std::map<std::string, long> tally{{"killed", 0}};  // "exit 0", "exit 1", ... "killed", "defect"
    std::map<std::string, long> failures_by_reason;  // exit-1 reasons, for review
    long tried = 0, defects = 0;
    double slowest = 0.0;
    for (long i = f.first(); i < f.first() + f.count(); ++i) {
        if (f.seconds > 0 && std::chrono::duration<double>(Clock::now() - start).count() > static_cast<double>(f.seconds)) break;
        const Mutant m = test::mutate_case(sources[static_cast<std::size_t>(i) % sources.size()], seed,
                                           static_cast<std::uint64_t>(i));
        const std::string command = i % 4 == 3 ? "modes" : "simulate";
        const std::string dir = test::make_temp_dir();
        const std::string path = dir + "/case.toml";
        const std::string out = dir + "/out";
        test::write_text(path, m.text);
        if (only >= 0) std::printf("fuzz: mutant %ld saved as %s\n", i, save_finding(m, seed, i).c_str());
        const CommandResult r = test::run_vibroimpact({command, path, "--out", out}, test::kFuzzLimitSeconds);
        ++tried;
        slowest = std::max(slowest, r.seconds);
        if (f.verbose) {
            const std::vector<std::string> err = test::lines_of(r.err);
            std::printf("fuzz: mutant %ld %s exit %d: %s\n", i, command.c_str(), r.exit_code,
                        err.empty() ? "" : err.back().substr(0, 200).c_str());
        }
        const test::FuzzRun run{dir, path, out, out + (command == "modes" ? "/modes.json" : "/summary.json"),
                                "a wall-clock time of " + std::to_string(static_cast<int>(test::kFuzzLimitSeconds)) + " s"};
        const std::string reason = test::run_defect(r, run);
        if (reason.empty()) {
            ++tally["exit " + std::to_string(r.exit_code)];
            if (r.exit_code == 1) ++failures_by_reason[test::lines_of(r.err).back().substr(0, 90)];
        } else {
            ++tally[r.hung ? "killed" : "defect"];
            if (++defects <= 20) {
                std::string steps;
                for (const std::string& s : m.steps) steps += "\n    " + s;
                ADD_FAILURE() << "mutant " << i << " of " << kSources[static_cast<std::size_t>(i) % kSources.size()]
                              << " (" << command << "): " << reason << "; saved as " << save_finding(m, seed, i)
                              << "; mutations:" << steps << "\n  exit " << r.exit_code << " after " << r.seconds
                              << " s, stderr: " << r.err.substr(0, 600);
            }
        }
        fs::remove_all(dir);
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    std::string counts;
    for (const auto& [what, n] : tally) counts += (counts.empty() ? "" : ", ") + what + ": " + std::to_string(n);
    std::printf("fuzz: %ld mutants in %.1f s (slowest run %.2f s): %s\n", tried, elapsed, slowest, counts.c_str());
    for (const auto& [what, n] : failures_by_reason) std::printf("fuzz: exit 1 x%ld: %s\n", n, what.c_str());
    RecordProperty("mutants", static_cast<int>(tried));
    RecordProperty("tally", counts);
    if (f.seconds <= 0) {
        EXPECT_EQ(tried, f.count());
    }
    EXPECT_GT(tried, 0);
}

}  // namespace
}  // namespace vi
