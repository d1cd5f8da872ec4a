// The [air] table and [[films]] entries (docs/squeeze-film.md §1): read with units, and every bad
// value refused with exit 2 and one line naming file, line and key, before any work.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "case_text_fixture.hpp"
#include "io/case_reader.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "support/text_checks.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

const std::string kSwitch = "examples/switch/cantilever_switch.toml";

std::string switch_text() { return test::read_text(test::source_path(kSwitch)); }

// 1-based line of the first line of text that starts with `start`.
int line_of(const std::string& text, const std::string& start) {
    int line = 1;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = text.find('\n', at);
        if (text.compare(at, start.size(), start) == 0) return line;
        if (end == std::string::npos) break;
        at = end + 1;
        ++line;
    }
    return 0;
}

// `simulate` on text: exit 2, one line "vibroimpact: error: FILE:LINE: KEY: ..." with `detail`, the
// line that of the first line starting with `line_start`; nothing written.
void expect_refused(const std::string& text, const std::string& key, const std::string& line_start,
                    const std::string& detail) {
    SCOPED_TRACE(key + " / " + detail);
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/case.toml";
    test::write_text(path, text);
    const auto r = test::run_vibroimpact({"simulate", path, "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(test::is_one_error_line(r.err)) << r.err;
    const std::string where = "vibroimpact: error: " + path + ":" + std::to_string(line_of(text, line_start)) + ": " + key + ":";
    EXPECT_EQ(r.err.rfind(where, 0), 0u) << r.err;
    EXPECT_NE(r.err.find(detail), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
    fs::remove_all(dir);
}

TEST(AirInput, DefaultsAndUnits) {
    const Case c = read_case_text(test::kBaseCase + "[air]\n", "a.toml");
    ASSERT_TRUE(c.air.has_value());
    EXPECT_EQ(c.air->pressure, 101325.0);
    EXPECT_EQ(c.air->temperature, 300.0);
    EXPECT_EQ(c.air->viscosity, 1.85e-5);
    EXPECT_DOUBLE_EQ(c.air->lambda(), 68e-9);
    EXPECT_TRUE(c.air->film);
    const Case d = read_case_text(test::kBaseCase +
                                      "[air]\npressure = \"10 kPa\"\ntemperature = \"350 K\"\nviscosity = \"0.02 mPa s\"\n"
                                      "film = false\n[[films]]\nfrom = 0.2\nto = 0.6\nside = \"above\"\ngap = \"3 um\"\n",
                                  "d.toml");
    EXPECT_EQ(d.air->pressure, 1e4);
    EXPECT_DOUBLE_EQ(d.air->viscosity, 2e-5);
    // lambda0 (p0 / p) (T / T0): 68 nm x 10.1325 x 350/300.
    EXPECT_DOUBLE_EQ(d.air->lambda(), 68e-9 * 10.1325 * 350.0 / 300.0);
    EXPECT_FALSE(d.air->film);
    ASSERT_EQ(d.films.size(), 1u);
    EXPECT_EQ(d.films[0].side, Side::above);
    EXPECT_DOUBLE_EQ(d.films[0].gap, 3e-6);
    const Case v = read_case_text(test::kBaseCase, "v.toml");
    EXPECT_FALSE(v.air.has_value());  // vacuum
}

TEST(AirInput, BadValuesAreRefusedWithFileLineAndKey) {
    const std::string base = switch_text();
    expect_refused(base + "[air]\npressure = \"0 Pa\"\n", "air.pressure", "pressure", "must be positive");
    expect_refused(base + "[air]\npressure = \"-3 kPa\"\n", "air.pressure", "pressure", "must be positive");
    expect_refused(base + "[air]\nviscosity = \"0 Pa s\"\n", "air.viscosity", "viscosity", "must be positive");
    expect_refused(base + "[air]\nmean_free_path = \"-1 nm\"\n", "air.mean_free_path", "mean_free_path",
                   "must be positive");
    expect_refused(base + "[air]\ntemperature = \"0 K\"\n", "air.temperature", "temperature", "must be positive");
    expect_refused(base + "[air]\nviscosity = \"2e-5 Pa\"\n", "air.viscosity", "viscosity", "a pressure");
    const std::string film = "[[films]]\nfrom = 0.2\nto = 0.6\ngap = \"1 um\"\n";
    expect_refused(base + "[air]\n[[films]]\nfrom = 0.2\nto = 1.2\ngap = \"1 um\"\n", "films[0].to", "to = 1.2",
                   "must lie in (0, 1]");
    expect_refused(base + "[air]\n[[films]]\nfrom = 0.5\nto = 0.5\ngap = \"1 um\"\n", "films[0].to", "to = 0.5",
                   "zero or negative length");
    expect_refused(base + "[air]\n[[films]]\nfrom = -0.1\nto = 0.5\ngap = \"1 um\"\n", "films[0].from", "from = -0.1",
                   "must lie in [0, 1)");
    expect_refused(base + "[air]\n[[films]]\nfrom = 0.2\nto = 0.5\n", "films[0].gap", "[[films]]", "missing required key");
    expect_refused(base + "[air]\n[[films]]\nfrom = 0.2\nto = 0.5\ngap = \"0 um\"\n", "films[0].gap", "gap = \"0 um\"",
                   "must be positive");
    expect_refused(base + film, "films[0]", "[[films]]", "needs an [air] table");
}

// The exact solver is for piecewise-linear forces: the paper's free impact (method = "exact", no
// electrode) with a film is told to use CVODE, naming the film.
TEST(AirInput, ExactSolverIsRefusedInAir) {
    const std::string text = test::read_text(test::source_path("examples/paper/free_impact_tip.toml")) +
                             "[air]\n[[films]]\nfrom = 0.0\nto = 1.0\ngap = \"1 um\"\n";
    expect_refused(text, "solver.method", "method = \"exact\"", "films[0] (squeeze film) is not; use method = \"cvode\"");
}

// The paper's beam over a 1 um film in air has squeeze number 0.99 at its first frequency, beyond
// the incompressible model's 0.3: `simulate` runs, and says so in one line on stderr, once.
TEST(AirInput, SimulateWarnsOnceAboveTheSqueezeNumberLimit) {
    std::string text = test::read_text(test::source_path("examples/paper/free_impact_tip.toml"));
    text.replace(text.find("method = \"exact\""), 16, "method = \"cvode\"");
    text.replace(text.find("horizon = \"150 us\""), 18, "horizon = \"5 us\"  ");
    text += "[air]\n[[films]]\nfrom = 0.0\nto = 1.0\ngap = \"1 um\"\n";
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/case.toml";
    test::write_text(path, text);
    const auto r = test::run_vibroimpact({"simulate", path, "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.rfind("vibroimpact: warning: " + path + ": films[0]: squeeze number 0.988", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.out.find("\"squeeze_number\""), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
