// Fuzz test of every physics: mutants of every example case file (found under examples/, so an
// example added later is in) run through every command that takes a case: simulate, pullin,
// pullin --dynamic, stiction, switch-report and air-q. The mutants are a designer's edits (a second
// electrode, a removed contact stop, electrodes to the beam's ends, an electrode gap below the stop's,
// voltages from 0 to 3 V_PI, waveforms at extreme rates, air, dielectrics, adhesion, meshes, end
// conditions, solver settings, magnitudes at 1e+-300; tests/support/designer_mutator.*) and the
// garbage of tests/support/case_mutator.* (values to extremes, wrong types, missing keys, broken
// syntax), alone or together. Every run must end within its limit with exit 0, 1 or 2
// (tests/support/fuzz_checks.hpp says what each requires). A failing run prints the mutant's edits,
// case and command and saves the case for replay.
//
// The runs go two at a time in child processes (VI_FUZZ_JOBS=N for another number), each limited in
// CPU time, so that a machine busy with other work does not turn a slow run into a kill. Deterministic:
// seed, count and each mutant's command are fixed (printed). The same knobs as FuzzCli's:
// VI_FUZZ_MUTANTS=N, VI_FUZZ_SECONDS=S, VI_FUZZ_SEED=N, VI_FUZZ_ONLY=I (mutant I alone, saved),
// VI_FUZZ_VERBOSE=1 (one line per run: exit code, CPU and wall time, last message line).

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "support/case_mutator.hpp"
#include "support/designer_mutator.hpp"
#include "support/fuzz_checks.hpp"
#include "support/parallel_runs.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi::fuzz_physics {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::Mutant;

// A run that has not ended by the limit is a hang, a defect. The limit is on CPU time, which other
// work on a shared machine does not stretch, with a wall-clock backstop for a run that waits without
// computing (300 s in Release, 600 s under the sanitizers).
constexpr test::RunLimits kLimits{test::kFuzzLimitSeconds, VI_SANITIZE_BUILD ? 600.0 : 300.0};

// The commands that take a case, with how often each is drawn (out of the sum), and the file a run
// that ends with exit 0 must have written. air-q runs 17 ring-down transients (4.7 s of CPU on the
// cantilever switch, 15 times its simulate), so it is drawn least, about 50 times in 3000.
struct Command {
    std::vector<std::string> args;   // before the case
    std::vector<std::string> after;  // after the case
    int weight;
    const char* writes;
};
const std::vector<Command> kCommands = {
    {{"simulate"}, {}, 20, "summary.json"},        {{"pullin"}, {}, 14, "pullin.json"},
    {{"pullin"}, {"--dynamic"}, 9, "pullin.json"}, {{"stiction"}, {}, 10, "stiction.json"},
    {{"switch-report"}, {}, 8, "report.html"},     {{"air-q"}, {}, 1, "air_q.csv"}};

std::string command_name(const Command& c) {
    std::string s = c.args.front();
    for (const std::string& a : c.after) s += " " + a;
    return s;
}

// Every example case file under examples/, in a fixed order.
std::vector<std::string> example_cases() {
    std::vector<std::string> out;
    const fs::path root = test::source_path("examples");
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (e.is_regular_file() && e.path().extension() == ".toml") out.push_back(fs::relative(e.path(), test::source_path("")).string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// V_PI of a case from `pullin --json`, or 0 when it has none.
double pullin_voltage(const std::string& path) {
    const CommandResult r = test::run_vibroimpact({"pullin", path, "--json"}, 120.0);
    if (r.exit_code != 0) return 0.0;
    const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
    if (j.is_discarded() || !j.contains("pullin") || !j["pullin"].is_object()) return 0.0;
    return j["pullin"].value("voltage_V", 0.0);
}

// Mutant i: its source, command and edits (a designer's, garbage, or a designer's then garbage).
struct Planned {
    std::size_t source = 0;
    std::size_t command = 0;
    Mutant mutant;
};

Planned plan(const std::vector<test::DesignerSource>& sources, std::uint64_t seed, std::uint64_t i) {
    Planned p;
    p.source = i % sources.size();
    std::mt19937_64 dice(seed * 0xBF58476D1CE4E5B9ULL + i);
    int total = 0;
    for (const Command& c : kCommands) total += c.weight;
    int roll = static_cast<int>(dice() % static_cast<std::uint64_t>(total));
    while (roll >= kCommands[p.command].weight) roll -= kCommands[p.command++].weight;
    const std::uint64_t kind = dice() % 10;
    if (kind < 6) {
        p.mutant = test::mutate_design(sources[p.source], seed, i);
    } else if (kind < 8) {
        p.mutant = test::mutate_case(sources[p.source].text, seed, i);
    } else {
        const Mutant d = test::mutate_design(sources[p.source], seed, i);
        p.mutant = test::mutate_case(d.text, seed, i);
        p.mutant.files = d.files;
        p.mutant.steps.insert(p.mutant.steps.begin(), d.steps.begin(), d.steps.end());
    }
    return p;
}

std::string write_mutant(const Mutant& m, const std::string& dir) {
    test::write_text(dir + "/case.toml", m.text);
    for (const auto& [name, text] : m.files) test::write_text(dir + "/" + name, text);
    return dir + "/case.toml";
}

// A failing mutant copied where the message says, to replay with the printed command.
std::string save_finding(const Mutant& m, std::uint64_t seed, long index) {
    const fs::path dir = fs::temp_directory_path() / "vi_fuzz_findings" /
                         ("physics-seed" + std::to_string(seed) + "-mutant" + std::to_string(index));
    fs::create_directories(dir);
    return write_mutant(m, dir.string());
}

struct Tally {
    std::map<std::string, long> exits;               // "exit 0", "exit 1", "exit 2", "defect"
    std::map<std::string, std::map<int, long>> by_command;
    std::map<std::string, long> failures_by_reason;  // exit-1 reasons, for review
    std::map<std::string, double> cpu;               // CPU seconds by command
    long tried = 0, defects = 0;
    double slowest = 0.0;                            // the most CPU one run took [s]
    std::string slowest_run;
};

TEST(FuzzPhysics, EveryMutantOfEveryExampleEndsInTimeUnderEveryCommand) {
    const test::FuzzSettings f = test::fuzz_settings();
    const std::uint64_t seed = f.seed;
    const long seconds = f.seconds;
    const long only = f.only;
    const bool verbose = f.verbose;
    const auto jobs = static_cast<std::size_t>(std::max(1L, test::env_number("VI_FUZZ_JOBS", 2)));

    const std::vector<std::string> names = example_cases();
    ASSERT_GE(names.size(), 10u) << "the examples are not where the test looks for them";
    std::vector<test::DesignerSource> sources;
    for (const std::string& n : names) {
        const std::string path = test::source_path(n);
        sources.push_back({test::read_text(path), pullin_voltage(path)});
        ASSERT_FALSE(sources.back().text.empty()) << n;
        std::printf("fuzz: source %zu %s (V_PI %s)\n", sources.size() - 1, n.c_str(),
                    sources.back().pullin_voltage > 0.0 ? (std::to_string(sources.back().pullin_voltage) + " V").c_str() : "none");
    }
    std::printf("fuzz: %s, %zu at a time, limit per run %.0f s of CPU (%.0f s of wall time)\n", f.describe().c_str(), jobs,
                kLimits.cpu_s, kLimits.wall_s);

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const long first = f.first();
    const long count = f.count();
    std::map<std::size_t, std::pair<Planned, std::string>> under_way;  // index -> plan, folder
    Tally t;
    t.exits["killed"] = 0;  // printed in the tally even when none was

    auto start_run = [&](std::size_t k) {
        const long i = first + static_cast<long>(k);
        Planned p = plan(sources, seed, static_cast<std::uint64_t>(i));
        const std::string dir = test::make_temp_dir();
        const std::string path = write_mutant(p.mutant, dir);
        if (only >= 0) std::printf("fuzz: mutant %ld saved as %s\n", i, save_finding(p.mutant, seed, i).c_str());
        const Command& c = kCommands[p.command];
        std::vector<std::string> argv{test::vibroimpact_path()};
        argv.insert(argv.end(), c.args.begin(), c.args.end());
        argv.push_back(path);
        argv.insert(argv.end(), c.after.begin(), c.after.end());
        argv.insert(argv.end(), {"--out", dir + "/out"});
        under_way.emplace(k, std::make_pair(std::move(p), dir));
        return argv;
    };
    auto run_done = [&](std::size_t k, const CommandResult& r) {
        const long i = first + static_cast<long>(k);
        const auto node = under_way.find(k);
        const Planned& p = node->second.first;
        const std::string& dir = node->second.second;
        const Command& c = kCommands[p.command];
        const std::string command = command_name(c);
        const test::FuzzRun run{dir, dir + "/case.toml", dir + "/out", dir + "/out/" + c.writes,
                                std::to_string(static_cast<int>(kLimits.cpu_s)) + " s of CPU or " +
                                    std::to_string(static_cast<int>(kLimits.wall_s)) + " s of wall time"};
        ++t.tried;
        t.cpu[command] += r.cpu_seconds;
        if (r.cpu_seconds > t.slowest) {
            t.slowest = r.cpu_seconds;
            t.slowest_run = "mutant " + std::to_string(i) + " of " + names[p.source] + " (" + command + "), " +
                            std::to_string(r.seconds) + " s of wall time";
        }
        if (verbose) {
            const std::vector<std::string> err = test::lines_of(r.err);
            std::printf("fuzz: mutant %ld %s %s exit %d %.2f s CPU %.2f s wall: %s\n", i, names[p.source].c_str(),
                        command.c_str(), r.exit_code, r.cpu_seconds, r.seconds,
                        err.empty() ? "" : err.back().substr(0, 200).c_str());
        }
        const std::string reason = test::run_defect(r, run);
        if (reason.empty()) {
            ++t.exits["exit " + std::to_string(r.exit_code)];
            ++t.by_command[command][r.exit_code];
            if (r.exit_code == 1) ++t.failures_by_reason[command + ": " + test::lines_of(r.err).back().substr(0, 100)];
        } else {
            ++t.exits[r.hung ? "killed" : "defect"];
            if (++t.defects <= 20) {
                std::string steps;
                for (const std::string& s : p.mutant.steps) steps += "\n    " + s;
                const std::string saved = save_finding(p.mutant, seed, i);
                ADD_FAILURE() << "mutant " << i << " of " << names[p.source] << ": " << reason
                              << "\n  replay: vibroimpact " << command.substr(0, command.find(' ')) << " " << saved
                              << (c.after.empty() ? "" : " " + c.after.front()) << " --out OUT"
                              << "\n  edits:" << steps << "\n  exit " << r.exit_code << " after " << r.cpu_seconds
                              << " s of CPU, " << r.seconds << " s of wall time, stderr: " << r.err.substr(0, 600) << "\n  the case:\n"
                              << p.mutant.text;
            }
        }
        fs::remove_all(dir);
        under_way.erase(node);
    };
    auto keep_going = [&] {
        return seconds <= 0 || std::chrono::duration<double>(Clock::now() - start).count() <= static_cast<double>(seconds);
    };
    test::run_in_parallel(static_cast<std::size_t>(count), jobs, kLimits, start_run, run_done, keep_going);

    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    std::string counts;
    for (const auto& [what, n] : t.exits) counts += (counts.empty() ? "" : ", ") + what + ": " + std::to_string(n);
    std::printf("fuzz: %ld mutants in %.1f s (slowest run %.2f s of CPU: %s): %s\n", t.tried, elapsed, t.slowest,
                t.slowest_run.c_str(), counts.c_str());
    for (const auto& [command, exits] : t.by_command) {
        std::string line;
        for (const auto& [code, n] : exits) line += " exit " + std::to_string(code) + ": " + std::to_string(n);
        std::printf("fuzz: %-17s%s; %.1f s of CPU\n", command.c_str(), line.c_str(), t.cpu[command]);
    }
    for (const auto& [what, n] : t.failures_by_reason) std::printf("fuzz: exit 1 x%ld: %s\n", n, what.c_str());
    RecordProperty("mutants", static_cast<int>(t.tried));
    RecordProperty("tally", counts);
    if (seconds <= 0) {
        EXPECT_EQ(t.tried, count);
    }
    EXPECT_GT(t.tried, 0);
}

}  // namespace
}  // namespace vi::fuzz_physics
