// Case files: the [initial], [[loads]] and [solver] tables, load tables in CSV files, and the checks
// that tie them to the beam and its supports. Each bad input fails with "FILE:LINE: KEY: reason".

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/case_reader.hpp"
#include "case_text_fixture.hpp"
#include "model/input_error.hpp"

namespace {

using vi::read_case_text;

const std::string& kBase = vi::test::kBaseCase;

// kBase with both ends clamped (still 10 lines: the material table is written inline).
const std::string kClamped =
    "name = \"t\"\nmaterial = { youngs_modulus = 2e11, density = 8900, poisson_ratio = 0.3 }\n[beam]\n"
    "length = \"100 um\"\nwidth = \"30 um\"\nthickness = \"2 um\"\nelements = 20\nright = \"clamped\"\n\n\n";

// The message of the InputError reading text throws, or "accepted".
std::string error_of(const std::string& text, const std::string& source = "bad.toml") {
    try {
        read_case_text(text, source);
    } catch (const vi::InputError& e) {
        return e.what();
    }
    return "accepted";
}

// Reading text fails with a one-line message starting with prefix.
void expect_error(const std::string& text, const std::string& prefix, const std::string& source = "bad.toml") {
    const std::string what = error_of(text, source);
    EXPECT_EQ(what.substr(0, prefix.size()), prefix) << "full message: " << what << "\ntext:\n" << text;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
}

// A folder of its own under the test temp dir, removed at the end of the test.
class TempFolder {
public:
    explicit TempFolder(const std::string& name) : path_(std::filesystem::path(::testing::TempDir()) / name) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempFolder() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;
    // Writes text to file name in the folder; returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        const std::string p = (path_ / name).string();
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }

private:
    std::filesystem::path path_;
};

const std::string kTableLoad = "[[loads]]\nposition = 1.0\namplitude = \"1 uN\"\nkind = \"table\"\ntable = \"g.csv\"\n";

TEST(CaseReaderTables, WithoutInitialTheBeamStartsAtRest) {
    const vi::Case c = read_case_text(kBase, "ok.toml");
    EXPECT_EQ(c.initial.kind, vi::InitialState::Kind::rest);
    EXPECT_EQ(c.initial.velocity_kind, vi::InitialState::Velocity::none);
    EXPECT_TRUE(c.loads.empty());
    EXPECT_EQ(c.solver.method, vi::SolverSettings::Method::automatic);
    EXPECT_EQ(c.solver.horizon, 0.0);
    EXPECT_EQ(c.solver.output_step, 0.0);
    EXPECT_DOUBLE_EQ(c.solver.settle_tolerance, 0.01);
}

TEST(CaseReaderTables, InitialDisplacementWithUniformVelocity) {
    const vi::Case c = read_case_text(
        kBase + "[initial]\nposition = 0.9\ndisplacement = \"1.5 um\"\nvelocity = \"-0.5 m/s\"\n", "ok.toml");
    EXPECT_EQ(c.initial.kind, vi::InitialState::Kind::displacement);  // the default kind in the table
    EXPECT_DOUBLE_EQ(c.initial.position, 0.9);
    EXPECT_DOUBLE_EQ(c.initial.displacement, 1.5e-6);
    EXPECT_EQ(c.initial.velocity_kind, vi::InitialState::Velocity::uniform);  // velocity alone: uniform
    EXPECT_DOUBLE_EQ(c.initial.velocity, -0.5);
}

TEST(CaseReaderTables, InitialForceWithModalVelocityAndRest) {
    vi::Case c = read_case_text(kBase + "[initial]\nkind = \"force\"\nforce = \"2 uN\"\nvelocity_shape = \"mode\"\n"
                                        "velocity_mode = 2\nvelocity = \"3 mm/s\"\n", "ok.toml");
    EXPECT_EQ(c.initial.kind, vi::InitialState::Kind::force);
    EXPECT_DOUBLE_EQ(c.initial.force, 2e-6);
    EXPECT_DOUBLE_EQ(c.initial.position, 1.0);
    EXPECT_EQ(c.initial.velocity_kind, vi::InitialState::Velocity::mode);
    EXPECT_EQ(c.initial.velocity_mode, 2);
    EXPECT_DOUBLE_EQ(c.initial.velocity, 3e-3);
    c = read_case_text(kBase + "[initial]\nkind = \"rest\"\nvelocity_shape = \"none\"\n", "ok.toml");
    EXPECT_EQ(c.initial.kind, vi::InitialState::Kind::rest);
    EXPECT_EQ(c.initial.velocity_kind, vi::InitialState::Velocity::none);
}

TEST(CaseReaderTables, LoadsOfEveryKind) {
    TempFolder dir("vi_case_tables_good");
    dir.write("g.csv", "t_s,g\n0,0\n\n1e-6, 1.0\r\n2e-6,0.5\n");
    const std::string text =
        kBase + "[[loads]]\nposition = 0.5\namplitude = \"1 uN\"\nkind = \"constant\"\n"
                "[[loads]]\nposition = 1.0\namplitude = -2e-6\nkind = \"step\"\nt_on = \"1 us\"\n"
                "[[loads]]\nposition = 0.25\namplitude = \"3 nN\"\nkind = \"harmonic\"\nfrequency = \"100 kHz\"\n"
                "phase = 1.5\noffset = 0.5\n" + kTableLoad;
    const vi::Case c = vi::read_case_file(dir.write("case.toml", text));
    ASSERT_EQ(c.loads.size(), 4u);
    using Kind = vi::TimeFunction::Kind;
    EXPECT_EQ(c.loads[0].time.kind, Kind::constant);
    EXPECT_DOUBLE_EQ(c.loads[0].position, 0.5);
    EXPECT_DOUBLE_EQ(c.loads[0].amplitude, 1e-6);
    EXPECT_EQ(c.loads[1].time.kind, Kind::step);
    EXPECT_DOUBLE_EQ(c.loads[1].amplitude, -2e-6);
    EXPECT_DOUBLE_EQ(c.loads[1].time.t_on, 1e-6);
    EXPECT_EQ(c.loads[2].time.kind, Kind::harmonic);
    EXPECT_DOUBLE_EQ(c.loads[2].amplitude, 3e-9);
    EXPECT_DOUBLE_EQ(c.loads[2].time.frequency_hz, 1e5);
    EXPECT_DOUBLE_EQ(c.loads[2].time.phase, 1.5);
    EXPECT_DOUBLE_EQ(c.loads[2].time.offset, 0.5);
    EXPECT_EQ(c.loads[3].time.kind, Kind::table);
    EXPECT_EQ(c.loads[3].time.times, (std::vector<double>{0.0, 1e-6, 2e-6}));
    EXPECT_EQ(c.loads[3].time.values, (std::vector<double>{0.0, 1.0, 0.5}));
}

TEST(CaseReaderTables, Solver) {
    const vi::Case c = read_case_text(kBase + "[solver]\nmethod = \"cvode\"\nhorizon = \"200 us\"\n"
                                              "output_step = \"10 ns\"\ngroup_gap = \"2 us\"\n"
                                              "settle_tolerance = 0.05\nrtol = 1e-8\nmin_search_step = 1e-12\n", "ok.toml");
    EXPECT_EQ(c.solver.method, vi::SolverSettings::Method::cvode);
    EXPECT_DOUBLE_EQ(c.solver.horizon, 200e-6);
    EXPECT_DOUBLE_EQ(c.solver.output_step, 10e-9);
    EXPECT_DOUBLE_EQ(c.solver.group_gap, 2e-6);
    EXPECT_DOUBLE_EQ(c.solver.settle_tolerance, 0.05);
    EXPECT_DOUBLE_EQ(c.solver.rtol, 1e-8);
    EXPECT_DOUBLE_EQ(c.solver.min_search_step, 1e-12);
}

TEST(CaseReaderTablesErrors, Initial) {
    const std::string t = kBase + "[initial]\n";  // the table header is line 11
    expect_error(t + "position = 1.0\n", "bad.toml:11: initial.displacement: missing required key");
    expect_error(t + "kind = \"force\"\n", "bad.toml:11: initial.force: missing required key");
    expect_error(t + "kind = \"lift\"\n", "bad.toml:12: initial.kind: must be one of \"rest\", \"displacement\"");
    expect_error(t + "kind = \"force\"\nforce = 1e-6\ndisplacement = \"1 um\"\n",
                 "bad.toml:14: initial.displacement: only with initial.kind = \"displacement\"");
    expect_error(t + "kind = \"rest\"\nforce = 1e-6\n", "bad.toml:13: initial.force: only with initial.kind = \"force\"");
    expect_error(t + "displacement = \"1 uN\"\n", "bad.toml:12: initial.displacement: unit \"uN\" is a force");
    expect_error(t + "kind = \"rest\"\nvelocity_shape = \"uniform\"\n",
                 "bad.toml:11: initial.velocity: missing required key");
    expect_error(t + "kind = \"rest\"\nvelocity_shape = \"none\"\nvelocity = 1\n",
                 "bad.toml:14: initial.velocity: only with initial.velocity_shape = \"uniform\" or \"mode\"");
    expect_error(t + "kind = \"rest\"\nvelocity = 1\nvelocity_mode = 2\n",
                 "bad.toml:14: initial.velocity_mode: only with initial.velocity_shape = \"mode\"");
    expect_error(t + "kind = \"rest\"\nvelocity = 1\nvelocity_shape = \"mode\"\nvelocity_mode = 0\n",
                 "bad.toml:15: initial.velocity_mode: must be at least 1");
    expect_error(t + "kind = \"rest\"\ntip = 1\n", "bad.toml:13: initial.tip: unknown key");
    for (const char* p : {"0", "1.5", "-0.2"}) {
        expect_error(t + "position = " + p + "\ndisplacement = \"1 um\"\n",
                     "bad.toml:12: initial.position: must lie in (0, 1] (x/l)");
    }
    expect_error(kClamped + "[initial]\ndisplacement = \"1 um\"\n",
                 "bad.toml:11: initial.position: lies at a clamped or pinned end, where v cannot move");
    EXPECT_EQ(error_of(kClamped + "[initial]\nkind = \"rest\"\n"), "accepted");  // nothing moves there
}

TEST(CaseReaderTablesErrors, Loads) {
    const std::string l = kBase + "[[loads]]\nposition = 0.5\namplitude = \"1 uN\"\n";  // header at line 11
    expect_error(l, "bad.toml:11: loads[0].kind: missing required key");
    expect_error(kBase + "[[loads]]\nkind = \"constant\"\n", "bad.toml:11: loads[0].position: missing required key");
    expect_error(l + "kind = \"step\"\n", "bad.toml:11: loads[0].t_on: missing required key");
    expect_error(l + "kind = \"harmonic\"\n", "bad.toml:11: loads[0].frequency: missing required key");
    expect_error(l + "kind = \"table\"\n", "bad.toml:11: loads[0].table: missing required key");
    expect_error(l + "kind = \"constant\"\nt_on = \"1 us\"\n", "bad.toml:15: loads[0].t_on: only with loads[0].kind = \"step\"");
    expect_error(l + "kind = \"step\"\nt_on = 0\nphase = 1\n",
                 "bad.toml:16: loads[0].phase: only with loads[0].kind = \"harmonic\"");
    expect_error(l + "kind = \"step\"\nt_on = 0\ntable = \"g.csv\"\n",
                 "bad.toml:16: loads[0].table: only with loads[0].kind = \"table\"");
    expect_error(l + "kind = \"harmonic\"\nfrequency = \"0 Hz\"\n", "bad.toml:15: loads[0].frequency: must be positive");
    expect_error(l + "kind = \"harmonic\"\nfrequency = \"1 us\"\n", "bad.toml:15: loads[0].frequency: unit \"us\" is a time");
    expect_error(l + "kind = \"step\"\nt_on = \"-1 us\"\n", "bad.toml:15: loads[0].t_on: must not be negative");
    expect_error(l + "kind = \"table\"\ntable = \"\"\n", "bad.toml:15: loads[0].table: must not be empty");
    expect_error(l + "kind = \"pulse\"\n", "bad.toml:14: loads[0].kind: must be one of \"constant\", \"step\"");
    expect_error(kBase + "[[loads]]\nposition = 0\namplitude = 1e-6\nkind = \"constant\"\n",
                 "bad.toml:12: loads[0].position: must lie in (0, 1] (x/l)");
    expect_error(kClamped + "[[loads]]\nposition = 1.0\namplitude = 1e-6\nkind = \"constant\"\n",
                 "bad.toml:12: loads[0].position: a load at a clamped or pinned end does nothing");
    expect_error(kBase + "[loads]\nposition = 0.5\n", "bad.toml:11: loads: expected an array of tables ([[loads]])");
    expect_error(l + "kind = \"constant\"\nforce = 1\n", "bad.toml:15: loads[0].force: unknown key");
}

TEST(CaseReaderTablesErrors, LoadTableFiles) {
    TempFolder dir("vi_case_tables_bad");
    const std::string csv = (std::filesystem::path(::testing::TempDir()) / "vi_case_tables_bad" / "g.csv").string();
    const std::string source = dir.write("case.toml", "");
    expect_error(kBase + kTableLoad, source + ":15: loads[0].table: cannot read \"" + csv + "\" (", source);
    const std::pair<const char*, std::string> bad[] = {
        {"", csv + ":1: empty table (expected the header row \"t_s,g\")"},
        {"t_s,g\n", csv + ":1: no rows below the header"},
        {"time,g\n0,1\n", csv + ":1: expected the header row \"t_s,g\", got \"time,g\""},
        {"0,1\n", csv + ":1: expected the header row \"t_s,g\""},
        {"t_s,g\n0,1\n1e-6;2\n", csv + ":3: expected 2 comma-separated columns (t_s,g), got \"1e-6;2\""},
        {"t_s,g\n0,1,2\n", csv + ":2: expected 2 comma-separated columns"},
        {"t_s,g\n0,1\n\n2e-6,x\n", csv + ":4: g: "},
        {"t_s,g\n0 s,1\n", csv + ":2: t_s: "},
        {"t_s,g\n0,1\nnan,2\n", csv + ":3: t_s: "},
        {"t_s,g\n0,1\n2e-6,1\n2e-6,0\n", csv + ":4: t_s: times must increase strictly down the table"},
    };
    for (const auto& [table, message] : bad) {
        dir.write("g.csv", table);
        expect_error(kBase + kTableLoad, message, source);
    }
}

TEST(CaseReaderTablesErrors, Solver) {
    const std::string s = kBase + "[solver]\n";  // header at line 11
    expect_error(s + "method = \"euler\"\n", "bad.toml:12: solver.method: must be one of \"auto\", \"exact\", \"cvode\"");
    expect_error(s + "horizon = 0\n", "bad.toml:12: solver.horizon: must be positive");
    expect_error(s + "horizon = \"1 us\"\noutput_step = \"-1 ns\"\n", "bad.toml:13: solver.output_step: must be positive");
    expect_error(s + "horizon = \"1 us\"\noutput_step = \"2 us\"\n",
                 "bad.toml:13: solver.output_step: must not exceed solver.horizon (1e-06 s)");
    expect_error(s + "output_step = \"2 us\"\nhorizon = \"1 us\"\n", "bad.toml:12: solver.output_step: must not exceed");
    expect_error(s + "group_gap = \"-1 us\"\n", "bad.toml:12: solver.group_gap: must not be negative");
    expect_error(s + "settle_tolerance = 1\n", "bad.toml:12: solver.settle_tolerance: must lie in (0, 1)");
    expect_error(s + "settle_tolerance = 0\n", "bad.toml:12: solver.settle_tolerance: must lie in (0, 1)");
    expect_error(s + "rtol = 1e-2\n", "bad.toml:12: solver.rtol: must lie in [1e-12, 1e-3]");
    expect_error(s + "min_search_step = 0\n", "bad.toml:12: solver.min_search_step: must lie in [1e-15, 1e-3]");
    expect_error(s + "min_search_step = 0.01\n", "bad.toml:12: solver.min_search_step: must lie in [1e-15, 1e-3]");
    expect_error(s + "horizon = \"1 um\"\n", "bad.toml:12: solver.horizon: unit \"um\" is a length");
    expect_error(s + "steps = 10\n", "bad.toml:12: solver.steps: unknown key");
}

TEST(CaseReaderTablesErrors, SupportsAboveAndBelowMustLeaveRoom) {
    const auto pair = [](const std::string& below, const std::string& above) {
        return kBase + "[[supports]]\nposition = 1.0\nstiffness = 50\n" + below +  // lines 11-14
               "[[supports]]\nposition = 1.0\nstiffness = 50\nside = \"above\"\n" + above;  // lines 15-19
    };
    expect_error(pair("gap = 0\n", "prestress = \"0.1 um\"\n"),
                 "bad.toml:19: supports[1].prestress: overlaps supports[0] on the other side (the surface below, "
                 "at v = 0 m, must lie under the surface above, at v = -1e-07 m)");
    expect_error(pair("prestress = \"0.3 um\"\n", "gap = \"0.2 um\"\n"),
                 "bad.toml:19: supports[1].gap: overlaps supports[0] on the other side");
    expect_error(pair("gap = 0\n", ""), "bad.toml:16: supports[1].position: overlaps supports[0]");  // both touch
    EXPECT_EQ(error_of(pair("gap = \"0.5 um\"\n", "gap = \"0.5 um\"\n")), "accepted");
    EXPECT_EQ(error_of(pair("prestress = \"0.2 um\"\n", "gap = \"0.3 um\"\n")), "accepted");
}

}  // namespace
