// Runs that cannot end, or cannot mean anything, are refused before they start
// (docs/case-files.md, "Limits"): each refusal exits 2 with one line naming the file, the line and the
// key (and the estimate where there is one), and writes nothing.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/case_checks.hpp"
#include "model/run_estimate.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "support/text_checks.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using test::run_vibroimpact;

const std::string kExample = "examples/paper/free_impact_tip.toml";

std::string example_text() { return test::read_text(test::source_path(kExample)); }

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
    return text;
}

// The example with n supports spread along the beam in place of its own.
std::string with_supports(std::size_t n) {
    const std::string text = example_text();
    const auto first = text.find("[[supports]]");
    const auto initial = text.find("[initial]");
    std::string supports;
    for (std::size_t k = 0; k < n; ++k) {
        supports += "[[supports]]\nposition = " + std::to_string(static_cast<double>(k + 1) / static_cast<double>(n)) +
                    "\nstiffness = \"1000 N/m\"\n\n";
    }
    return text.substr(0, first) + supports + text.substr(initial);
}

struct Refusal {
    const char* what;
    std::string text;
    const char* key;      // the key the message must name
    const char* detail;   // a word the message must hold (the estimate or the limit)
    const char* command;  // "simulate" or "modes"
};

// Runs the command on text with --out; expects exit 2, one error line naming the file, the key and
// the detail, and no output folder.
void expect_refused(const Refusal& r) {
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/case.toml";
    test::write_text(path, r.text);
    const std::string out = dir + "/out";
    const auto t0 = std::chrono::steady_clock::now();
    const auto res = run_vibroimpact({r.command, path, "--out", out});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(res.exit_code, 2) << r.what << ": " << res.err;
    EXPECT_TRUE(test::is_one_error_line(res.err)) << r.what << ": " << res.err;
    EXPECT_EQ(res.err.rfind("vibroimpact: error: " + path + ":", 0), 0u) << r.what << ": names no file: " << res.err;
    EXPECT_NE(res.err.find(std::string(r.key) + ":"), std::string::npos) << r.what << ": names no key: " << res.err;
    EXPECT_NE(res.err.find(r.detail), std::string::npos) << r.what << ": says no " << r.detail << ": " << res.err;
    EXPECT_FALSE(fs::exists(out)) << r.what << " wrote output";
    // Refused before any work: well under the time a run would take (10 s allows a sanitizer build).
    EXPECT_LT(seconds, 10.0) << r.what;
    fs::remove_all(dir);
}

TEST(Refusals, OutputStepTooFineForMemory) {
    const std::string good = example_text();
    expect_refused({"1e-15 s", replace(good, "output_step = \"10 ns\"", "output_step = \"1e-15 s\""),
                    "solver.output_step", "1.5e+11 samples", "simulate"});
    expect_refused({"1e-15 s estimate", replace(good, "output_step = \"10 ns\"", "output_step = \"1e-15 s\""),
                    "solver.output_step", "TB of time history", "simulate"});
    expect_refused({"1e-320 s (subnormal)", replace(good, "output_step = \"10 ns\"", "output_step = \"1e-320 s\""),
                    "solver.output_step", "subnormal", "simulate"});
}

// Found by the fuzz test (seed 20250611, mutants 6586 and 7513 of free_impact_prestress.toml): a
// horizon of 30 ms, or an output step of 0.01 ns, asked for 3e6 samples and ran past 20 s.
TEST(Refusals, MoreThanAMillionSamples) {
    const std::string prestress = test::read_text(test::source_path("examples/paper/free_impact_prestress.toml"));
    expect_refused({"30 ms at 10 ns", replace(prestress, "horizon = \"30 us\"", "horizon = \"30 ms\""),
                    "solver.output_step", "at most 1e+06 samples", "simulate"});
    expect_refused({"0.01 ns", replace(prestress, "output_step = \"10 ns\"", "output_step = \"0.01 ns\""),
                    "solver.output_step", "3e+06 samples", "simulate"});
}

// Found by the fuzz test (seed 20250611, mutant 66): a load table naming /dev/zero was read without
// end; a device as the case file itself too.
TEST(Refusals, DevicesAreNotRead) {
    expect_refused({"table /dev/zero",
                    example_text() + "\n[[loads]]\nposition = 0.5\namplitude = \"1 uN\"\nkind = \"table\"\n"
                                     "table = \"/dev/zero\"\n",
                    "loads[0].table", "not a regular file or a pipe", "simulate"});
    const auto r = run_vibroimpact({"simulate", "/dev/zero"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err, "vibroimpact: error: /dev/zero: cannot read file (not a regular file or a pipe)\n");
}

TEST(Refusals, ElementsBeyondTheDocumentedMaxima) {
    const std::string good = example_text();
    // 100000 used to give "not positive definite" (exit 1) after the eigen solve.
    for (const char* command : {"simulate", "modes"}) {
        expect_refused({"100000 elements", replace(good, "elements = 50", "elements = 100000"), "beam.elements",
                        "at most 2000", command});
    }
    expect_refused({"exact transient", replace(good, "elements = 50", "elements = 401"), "beam.elements",
                    "at most 400", "simulate"});
    expect_refused({"cvode transient",
                    replace(replace(good, "elements = 50", "elements = 401"), "method = \"exact\"", "method = \"cvode\""),
                    "beam.elements", "at most 400", "simulate"});
}

// The modal maximum is a working mesh, not just an accepted one: its first frequency is within
// roundoff (3.2e-4 measured, docs/case-files.md) of the closed form 113.8099 kHz.
TEST(Refusals, ModalMaximumWorks) {
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/case.toml";
    test::write_text(path, replace(example_text(), "elements = 50", "elements = " + std::to_string(kMaxElements)));
    const auto r = run_vibroimpact({"modes", path, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double f1 = j["unsupported"]["bending"][0]["frequency_hz"].get<double>();
    EXPECT_NEAR(f1, 113809.9, 1e-3 * 113809.9);
    fs::remove_all(dir);
}

TEST(Refusals, TooManySupports) {
    expect_refused({"101 supports", with_supports(kMaxSupports + 1), "supports[100]", "at most 100", "simulate"});
    // 10^5 supports: refused at once (the pairwise checks are never reached).
    expect_refused({"100000 supports", with_supports(100000), "supports[100]", "it has 100000", "simulate"});
}

TEST(Refusals, AbsurdMagnitudes) {
    const std::string good = example_text();
    const std::vector<Refusal> cases = {
        {"modulus 1e308", replace(good, "youngs_modulus = \"207 GPa\"", "youngs_modulus = 1e308"),
         "material.youngs_modulus", "1e+308", "simulate"},
        {"modulus 1e-320", replace(good, "youngs_modulus = \"207 GPa\"", "youngs_modulus = 1e-320"),
         "material.youngs_modulus", "subnormal", "simulate"},
        {"density 1e308", replace(good, "density = \"8902 kg/m^3\"", "density = 1e308"), "material.density", "1e+308",
         "modes"},
        {"stiffness 1e308", replace(good, "stiffness = \"1000 N/m\"", "stiffness = 1e308"), "supports[0].stiffness",
         "1e+308", "simulate"},
        {"stiffness 1e-320", replace(good, "stiffness = \"1000 N/m\"", "stiffness = 1e-320"), "supports[0].stiffness",
         "subnormal", "simulate"},
        {"displacement 1e308", replace(good, "displacement = \"1 um\"", "displacement = 1e308"), "initial.displacement",
         "1e+308", "simulate"},
        {"displacement 1e-320", replace(good, "displacement = \"1 um\"", "displacement = 1e-320"),
         "initial.displacement", "subnormal", "simulate"},
        {"length 1e-320", replace(good, "length = \"117 um\"", "length = 1e-320"), "beam.length", "subnormal", "modes"},
        {"a section whose I underflows", replace(good, "thickness = \"2 um\"", "thickness = 1e-45"), "beam.thickness",
         "second moment", "simulate"},
        {"contact 4e10 times the beam's EI/l^3", replace(good, "stiffness = \"1000 N/m\"", "stiffness = 1e11"),
         "supports[0].stiffness", "EI/l^3", "simulate"},
        {"contact damper 1e10 times critical", replace(good, "damping_ratio = 0.2 ", "damping_ratio = 1e10 "),
         "supports[0].damping_ratio", "EI/l^3", "simulate"},
        {"a point that cannot be lifted", replace(good, "position = 1.0\ndisplacement", "position = 1e-90\ndisplacement"),
         "initial.position", "does not move", "simulate"},
    };
    for (const Refusal& r : cases) expect_refused(r);
}

TEST(Refusals, SupportTooCloseToAnEnd) {
    // A node 1e-5 l from the free end: its element made K "not positive definite" (exit 1).
    const std::string text =
        replace(example_text(), "position = 1.0         # x0/l", "position = 0.99999         # x0/l");
    for (const char* command : {"simulate", "modes"}) {
        expect_refused({"support 1e-5 l from the end", text, "supports[0].position", "too short", command});
    }
}

TEST(Refusals, YearLongHorizon) {
    const std::string good = example_text();
    // The zero-gap beam bounces at ever smaller amplitude; at a year's horizon the event times
    // would be lost to rounding (and the bouncing reaches roundoff long before).
    for (const char* horizon : {"\"3.15e7 s\"", "31536000.0"}) {
        expect_refused({"a year", replace(good, "horizon = \"150 us\"", std::string("horizon = ") + horizon),
                        "solver.horizon", "shortest time scale", "simulate"});
    }
}

TEST(RunEstimate, MemoryOfTheExampleAndItsLimits) {
    Case c;
    c.beam = {117e-6, 30e-6, 2e-6, 50, EndCondition::clamped, EndCondition::free};
    c.material = {207e9, 8902.0, 0.31, false};
    c.supports.push_back(Support{});
    c.supports.back().stiffness = 1000.0;
    c.solver.horizon = 150e-6;
    c.solver.output_step = 10e-9;
    const RunEstimate e = estimate_run(c);
    EXPECT_EQ(e.bending_dofs, 102.0);  // 52 nodes with v and theta, minus the clamp's two
    EXPECT_NEAR(e.omega1, 715088.5, 1.0);  // the closed form; the FE value at m = 50 is 715088.48
    EXPECT_EQ(e.samples, 15001.0);
    EXPECT_EQ(e.history_bytes, 15001.0 * 12 * kHistoryBytesPerValue);
    EXPECT_TRUE(check_transient_run(c, true, memory_budget_bytes()).empty());
    // The same run on a machine that allows 1 MB: the matrices alone are refused.
    const auto small = check_transient_run(c, false, 1e6);
    ASSERT_EQ(small.size(), 1u);
    EXPECT_EQ(small[0].key, "beam.elements");
    // A history that a sweep does not keep (exact solver) is not counted; CVODE keeps it always.
    c.solver.output_step = 1e-15;
    EXPECT_TRUE(check_transient_run(c, false, memory_budget_bytes()).empty());
    c.solver.method = SolverSettings::Method::cvode;
    ASSERT_FALSE(check_transient_run(c, false, memory_budget_bytes()).empty());
    EXPECT_EQ(check_transient_run(c, false, memory_budget_bytes())[0].key, "solver.output_step");
    EXPECT_GT(memory_budget_bytes(), 0.0);
    EXPECT_LE(memory_budget_bytes(), kMemoryCap);
    // The reading kept for a second on the thread is the one the files give now.
    EXPECT_EQ(memory_budget_bytes(), read_memory_budget_bytes());
    EXPECT_EQ(bytes_text(1.2e13), "12 TB");
    EXPECT_EQ(bytes_text(512), "512 bytes");
}

// Every example of the docs stays accepted by the magnitude checks.
TEST(RunEstimate, ExamplesPassEveryCheck) {
    for (const char* name : {"cantilever.toml", "free_impact_tip.toml", "free_impact_prestress.toml"}) {
        const auto r = run_vibroimpact({"modes", test::source_path(std::string("examples/paper/") + name)});
        EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
    }
}

}  // namespace
}  // namespace vi
