// `vibroimpact plot DIR` end to end: the figures of a simulate, a modes and a sweep folder (one and two
// varying axes), their size and units, and the refusals (not a run folder, a corrupt CSV, no gnuplot).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using test::read_text;
using test::run_vibroimpact;

// The width of a PNG image from its IHDR chunk [px]; 0 when the bytes are not a PNG.
std::uint32_t png_width(const std::string& png) {
    if (png.size() < 24 || png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || png.compare(12, 4, "IHDR") != 0) return 0;
    std::uint32_t w = 0;
    for (int i = 16; i < 20; ++i) w = (w << 8) | static_cast<unsigned char>(png[static_cast<std::size_t>(i)]);
    return w;
}

// The run folders, made once for every test here.
class CliPlot : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        root_ = test::make_temp_dir();
        const std::string tip = test::source_path("examples/paper/free_impact_tip.toml");
        runs_ok_ = run_vibroimpact({"simulate", tip, "--out", root_ + "/sim"}).exit_code == 0 &&
                   run_vibroimpact({"modes", test::source_path("examples/paper/cantilever.toml"), "--out", root_ + "/modes"}).exit_code == 0 &&
                   run_vibroimpact({"sweep", tip, "--set", "supports[0].position=0.4:1:5", "--out", root_ + "/sweep1"}).exit_code == 0 &&
                   run_vibroimpact({"sweep", tip, "--set", "supports[0].position=0.6:1:3", "--set", "supports[0].stiffness=log:100:10000:3",
                                    "--out", root_ + "/sweep2"})
                           .exit_code == 0;
    }
    static void TearDownTestSuite() { fs::remove_all(root_); }

    void SetUp() override { ASSERT_TRUE(runs_ok_) << "simulate, modes or sweep failed in " << root_; }

    // Runs plot on a folder and expects success; returns what it printed.
    static std::string plot(const std::string& dir) {
        const auto r = run_vibroimpact({"plot", dir});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.out.find(dir + "/plots/"), std::string::npos) << r.out;
        return r.out;
    }

    // Checks one figure's files: a PNG at least 2000 px wide and of a drawn figure's size, an SVG
    // holding each of `labels` (the axis labels with their units).
    static void expect_figure(const std::string& dir, const std::string& name, const std::vector<std::string>& labels) {
        const std::string png = read_text(dir + "/" + name + ".png"), svg = read_text(dir + "/" + name + ".svg");
        EXPECT_GE(png_width(png), 2000u) << name;
        EXPECT_GT(png.size(), 10000u) << name;
        EXPECT_NE(svg.find("<svg"), std::string::npos) << name;
        EXPECT_GT(svg.size(), 10000u) << name;
        EXPECT_TRUE(fs::exists(dir + "/" + name + ".gp")) << name;
        for (const std::string& l : labels) EXPECT_NE(svg.find(l), std::string::npos) << name << ": no '" << l << "'";
    }

    static inline std::string root_;
    static inline bool runs_ok_ = false;
};

// The largest value of a CSV column (by header name) of a file [as written].
double column_max(const std::string& path, const std::string& column) {
    std::istringstream in(read_text(path));
    std::string line, cell;
    std::getline(in, line);
    std::istringstream head(line);
    int k = 0, at = -1;
    while (std::getline(head, cell, ',')) {
        if (cell == column) at = k;
        ++k;
    }
    EXPECT_GE(at, 0) << path << ": no column " << column;
    double m = -INFINITY;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        for (int i = 0; std::getline(row, cell, ','); ++i) {
            if (i == at) m = std::max(m, std::stod(cell));
        }
    }
    return m;
}

TEST_F(CliPlot, SimulateFolderGivesTimeHistoriesForcesEnergyAndPhasePortrait) {
    plot(root_ + "/sim");
    const std::string out = root_ + "/sim/plots";
    // The case: released from 1 µm, 150 µs horizon, contact forces of tens of µN.
    expect_figure(out, "transient_displacement", {"time  [µs]", "displacement  [µm]", "contact 0 (x/l = 1)", "surface of support 0"});
    expect_figure(out, "transient_force", {"time  [µs]", "force  [µN]"});
    expect_figure(out, "transient_energy", {"time  [µs]", "energy  [pJ]", "kinetic"});
    expect_figure(out, "transient_velocity", {"velocity  [mm/s]"});
    expect_figure(out, "transient_phase", {"tip displacement  [µm]", "tip velocity  [mm/s]"});
    // The drawn data are the history's to the last digit, in SI under the same names; the scripts
    // scale them to the axes' units.
    const double tip_m = column_max(root_ + "/sim/history.csv", "tip_m");
    EXPECT_EQ(column_max(out + "/transient_displacement.csv", "tip_m"), tip_m);
    const double force_n = column_max(root_ + "/sim/history.csv", "contact0_force_n");
    EXPECT_EQ(column_max(out + "/transient_force.csv", "contact0_force_n"), force_n);
    EXPECT_NE(read_text(out + "/transient_displacement.gp").find("using ($1*1000000):($2*1000000)"), std::string::npos);
}

TEST_F(CliPlot, SimulateFiguresLeaveOutZeroTermsAndCarryTheCaseName) {
    const std::string said = plot(root_ + "/sim");
    const std::string out = root_ + "/sim/plots";
    // No electrode and no load: the electrical energy and the external work are zero throughout.
    const std::string energy = read_text(out + "/transient_energy.svg");
    EXPECT_EQ(energy.find("electrical"), std::string::npos);
    EXPECT_EQ(energy.find("external work"), std::string::npos);
    EXPECT_NE(said.find("electrical_j (zero throughout)"), std::string::npos) << said;
    EXPECT_NE(said.find("external_work_j (zero throughout)"), std::string::npos) << said;
    EXPECT_NE(energy.find("Energy ledger - paper-free-impact-tip"), std::string::npos);
    // The figures' data hold what 2400 px can show, not copies of the history.
    std::uintmax_t copied = 0;
    for (const auto& e : fs::directory_iterator(out)) {
        if (e.path().extension() == ".csv") copied += fs::file_size(e.path());
    }
    EXPECT_LT(copied, fs::file_size(root_ + "/sim/history.csv"));
}

TEST_F(CliPlot, ModesFolderGivesShapesWithNodalPoints) {
    plot(root_ + "/modes");
    const std::string out = root_ + "/modes/plots";
    expect_figure(out, "modes_unsupported", {"x/l", "mode 1: 113.8 kHz"});
    expect_figure(out, "modes_supported", {"x/l", "mode 1: 499.1 kHz"});
    // The free cantilever's second mode has its node at x/l = 0.7834 (modes.json), drawn at zero.
    const std::string nodes = read_text(out + "/modes_unsupported_nodes.csv");
    EXPECT_NE(nodes.find("0.7834"), std::string::npos) << nodes;
    EXPECT_LE(column_max(out + "/modes_unsupported.csv", "v_1_over_peak"), 1.0 + 1e-9);
    // Titled with the case's name, which modes.json records.
    for (const char* figure : {"modes_unsupported", "modes_supported"}) {
        EXPECT_NE(read_text(out + "/" + figure + ".svg").find("paper-cantilever"), std::string::npos) << figure;
        EXPECT_NE(read_text(out + "/" + figure + ".gp").find(" - paper-cantilever"), std::string::npos) << figure;
    }
}

TEST_F(CliPlot, OneAxisSweepGivesEachQuantityAgainstTheAxis) {
    const std::string said = plot(root_ + "/sweep1");
    const std::string out = root_ + "/sweep1/plots";
    // One figure per family: the times together (T, T1, T2 and the impacts' onsets in µs), the
    // forces together, the dimensionless tau's together; a count alone.
    expect_figure(out, "sweep_times", {"supports[0].position  [x/l]", "Times  [µs]", ">T<", ">T1<", "impact1 t on"});
    expect_figure(out, "sweep_forces", {"supports[0].position  [x/l]", "impact1 peak force", "impact2 peak force"});
    expect_figure(out, "sweep_tau", {">tau<", ">tau1<", ">tau2<"});
    EXPECT_TRUE(fs::exists(out + "/sweep_impacts.png"));
    EXPECT_FALSE(fs::exists(out + "/sweep_T_s.png"));
    // A column with one value throughout (every first impact hits support 0) is not drawn, and said.
    EXPECT_FALSE(fs::exists(out + "/sweep_impact1_support.png"));
    EXPECT_NE(said.find("impact1_support (constant: 0)"), std::string::npos) << said;
    std::size_t figures = 0;
    for (const auto& e : fs::directory_iterator(out)) figures += e.path().extension() == ".png";
    EXPECT_LE(figures, 12u) << "families, not one figure per column";
    // Every figure is titled with the case's name.
    EXPECT_NE(read_text(out + "/sweep_times.svg").find("paper-free-impact-tip"), std::string::npos);
    // Text columns are not drawn, and the command says so.
    EXPECT_FALSE(fs::exists(out + "/sweep_status.png"));
    EXPECT_FALSE(fs::exists(out + "/sweep_Tp_reason.png"));
    EXPECT_NE(said.find("Not drawn: Tp_reason (text)"), std::string::npos) << said;
    EXPECT_NE(said.find("status (text)"), std::string::npos) << said;
}

TEST_F(CliPlot, TwoAxisSweepGivesHeatMaps) {
    plot(root_ + "/sweep2");
    const std::string out = root_ + "/sweep2/plots";
    expect_figure(out, "sweep_T_s", {"supports[0].position  [x/l]", "supports[0].stiffness  [N/m]", "T  [µs]"});
    // One cell per grid point that has a value: 3 x 3, and a header.
    const std::string data = read_text(out + "/sweep_impacts.csv");
    EXPECT_EQ(std::count(data.begin(), data.end(), '\n'), 10) << data;
    EXPECT_NE(read_text(out + "/sweep_T_s.gp").find("set logscale y"), std::string::npos);
}

TEST_F(CliPlot, OutOptionChoosesTheFolder) {
    const std::string out = root_ + "/elsewhere";
    const auto r = run_vibroimpact({"plot", root_ + "/modes", "--out", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(out + "/modes_supported.svg"));
}

TEST_F(CliPlot, NotARunFolderIsBadInputNamingIt) {
    const std::string dir = root_ + "/empty";
    fs::create_directories(dir);
    const auto r = run_vibroimpact({"plot", dir});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(dir + ": not a run folder"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/plots"));
    const auto missing = run_vibroimpact({"plot", root_ + "/no-such"});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("no-such: no such folder"), std::string::npos) << missing.err;
}

TEST_F(CliPlot, CorruptCsvIsBadInputNamingFileAndLine) {
    const std::string dir = root_ + "/corrupt";
    fs::create_directories(dir);
    std::string history = read_text(root_ + "/sim/history.csv");
    // Line 5 loses a cell; then a run of sweep.csv with a cell that is no number in a numeric file.
    std::size_t at = 0;
    for (int line = 1; line < 5; ++line) at = history.find('\n', at) + 1;
    history.replace(at, history.find(',', at) + 1 - at, "");
    test::write_text(dir + "/history.csv", history);
    const auto r = run_vibroimpact({"plot", dir});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(dir + "/history.csv:5: expected 13 comma-separated cells"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/plots"));

    const std::string sweep = root_ + "/sweep-no-json";
    fs::create_directories(sweep);
    fs::copy_file(root_ + "/sweep1/sweep.csv", sweep + "/sweep.csv");
    const auto s = run_vibroimpact({"plot", sweep});
    EXPECT_EQ(s.exit_code, 2);
    EXPECT_NE(s.err.find(sweep + "/sweep.json: missing"), std::string::npos) << s.err;
}

TEST_F(CliPlot, MissingGnuplotSaysWhatToInstallAndWritesNothing) {
    const auto r = run_vibroimpact({"plot", root_ + "/modes", "--out", root_ + "/no-gnuplot", "--gnuplot", root_ + "/no/gnuplot"});
    // As for every command that draws: a missing program is a failure (1), not bad input (2).
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("apt-get install gnuplot-nox"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(root_ + "/no-gnuplot"));
    // The same for paper, before its minutes of work.
    const auto p = run_vibroimpact({"paper", "--out", root_ + "/no-paper", "--gnuplot", root_ + "/no/gnuplot"});
    EXPECT_EQ(p.exit_code, 1);
    EXPECT_NE(p.err.find("apt-get install gnuplot-nox"), std::string::npos) << p.err;
    EXPECT_FALSE(fs::exists(root_ + "/no-paper"));
}

}  // namespace
}  // namespace vi
