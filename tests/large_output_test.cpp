// Results that are large, or whose figure fails: `fit` on a million-sample trajectory writes its
// results and a figure drawn from a thinned copy; a figure gnuplot cannot draw never throws away
// fit's or optimize's numbers; `plot` draws a simulate folder whose history is larger than the
// whole-file readers take, and sweeps of many points from thinned copies.

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "impacts/simulation.hpp"
#include "io/case_reader.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

std::string free_impact_example() { return test::source_path("examples/paper/free_impact_tip.toml"); }

std::size_t line_count_of(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

void append_shortest(std::string& out, double v) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, end);
}

// A gnuplot that fails at once, as one that cannot draw a figure does.
std::string gnuplot_that_fails(const std::string& dir) {
    const std::string path = dir + "/gnuplot-fails";
    test::write_text(path, "#!/bin/sh\necho 'line 1: cannot draw this' >&2\nexit 3\n");
    chmod(path.c_str(), 0755);
    return path;
}

TEST(LargeOutput, AMillionSampleFitWritesItsResultsAndAFigureFromAThinnedCopy) {
    const std::string dir = test::make_temp_dir();
    // The example's tip over 9.99999 us every 10 ps: 10^6 samples (the most a history may hold).
    Case truth = read_case_file(free_impact_example());
    truth.solver.horizon = 9.99999e-6;
    truth.solver.output_step = 1e-11;
    SimulationOptions o;
    o.energy = false;
    const SimulationRun run = run_simulation(truth, o);
    const auto& h = run.result.history;
    ASSERT_EQ(h.t.size(), 1000000u);
    // The columns of a simulate history.csv the fit does not read come along, as when history.csv
    // itself is the data: some 100 MB, more than the whole-file readers take (64 MiB).
    std::string text = "t_s,tip_m,tip_velocity_m_s,contact0_m,contact0_velocity_m_s,contact0_force_n\n";
    text.reserve(std::size_t{120} << 20);
    for (std::size_t k = 0; k < h.t.size(); ++k) {
        for (const double v : {h.t[k], h.watched_v[k], h.watched_velocity[k], h.contact_v[0][k], h.contact_velocity[0][k]}) {
            append_shortest(text, v);
            text += ',';
        }
        append_shortest(text, h.contact_force[0][k]);
        text += '\n';
    }
    test::write_text(dir + "/tip.csv", text);
    EXPECT_GT(text.size(), std::size_t{64} << 20);
    text.clear();
    text.shrink_to_fit();
    const auto r = test::run_vibroimpact({"fit", free_impact_example(), "--data", dir + "/tip.csv", "--fit", "supports[0].stiffness=500:2000",
                                          "--out", dir + "/out"});
    std::printf("fit of 10^6 samples: exit %d in %.1f s\n", r.exit_code, r.seconds);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(test::read_text(dir + "/out/fit.json").find("\"estimate\""), std::string::npos);
    EXPECT_EQ(line_count_of(test::read_text(dir + "/out/fit_residuals.csv")), 1000001u);
    // The figure's data: the thinned copy (at most 2 400 slices x 8 rows), and an image of a few MB.
    const std::size_t drawn = line_count_of(test::read_text(dir + "/out/fit.csv"));
    EXPECT_LT(drawn, 19202u);
    EXPECT_GT(drawn, 2400u);
    EXPECT_LT(fs::file_size(dir + "/out/fit.svg"), std::uintmax_t{16} << 20);
    EXPECT_GT(fs::file_size(dir + "/out/fit.png"), 10000u);
    fs::remove_all(dir);
}

TEST(LargeOutput, AFigureThatCannotBeDrawnNeverThrowsAwayTheResults) {
    const std::string dir = test::make_temp_dir();
    const std::string gnuplot = gnuplot_that_fails(dir);
    // fit: the results written, the failure said in one line, exit 1.
    {
        Case c = read_case_file(free_impact_example());
        c.solver.horizon = 10e-6;
        c.solver.output_step = 100e-9;
        SimulationOptions o;
        o.energy = false;
        const SimulationRun run = run_simulation(c, o);
        std::string text = "t_s,tip_m\n";
        for (std::size_t k = 0; k < run.result.history.t.size(); ++k) {
            append_shortest(text, run.result.history.t[k]);
            text += ',';
            append_shortest(text, run.result.history.watched_v[k]);
            text += '\n';
        }
        test::write_text(dir + "/tip.csv", text);
    }
    const auto fit = test::run_vibroimpact({"fit", free_impact_example(), "--data", dir + "/tip.csv", "--fit", "supports[0].stiffness",
                                            "--gnuplot", gnuplot, "--out", dir + "/fit"});
    EXPECT_EQ(fit.exit_code, 1) << fit.err;
    EXPECT_EQ(line_count_of(fit.err), 1u) << fit.err;
    EXPECT_NE(fit.err.find("the figure was not drawn (gnuplot failed: line 1: cannot draw this)"), std::string::npos) << fit.err;
    EXPECT_TRUE(fs::exists(dir + "/fit/fit.json"));
    EXPECT_TRUE(fs::exists(dir + "/fit/fit_residuals.csv"));
    EXPECT_FALSE(fs::exists(dir + "/fit/fit.png"));
    EXPECT_NE(fit.out.find("supports[0].stiffness = "), std::string::npos) << fit.out;

    // optimize: the same, and its journal is gone (the search is complete).
    const auto opt = test::run_vibroimpact({"optimize", free_impact_example(), "--vary", "supports[0].position=0.5:1", "--minimize", "z_max",
                                            "--max-evals", "6", "--threads", "1", "--gnuplot", gnuplot, "--out", dir + "/opt"});
    EXPECT_EQ(opt.exit_code, 1) << opt.err;
    EXPECT_EQ(line_count_of(opt.err), 1u) << opt.err;
    EXPECT_NE(opt.err.find("the convergence figure was not drawn"), std::string::npos) << opt.err;
    EXPECT_TRUE(fs::exists(dir + "/opt/optimize.json"));
    EXPECT_TRUE(fs::exists(dir + "/opt/evaluations.csv"));
    EXPECT_FALSE(fs::exists(dir + "/opt/optimize.journal"));
    fs::remove_all(dir);
}

TEST(LargeOutput, PlotDrawsASimulateFolderLargerThanTheWholeFileReadersTake) {
    const std::string dir = test::make_temp_dir();
    // 400 001 samples: a history.csv of about 80 MB (the whole-file readers stop at 64 MiB).
    std::string c = test::read_text(free_impact_example());
    const auto set = [&](const std::string& key, const std::string& value) {
        const std::size_t at = c.find("\n" + key + " ");
        ASSERT_NE(at, std::string::npos) << key;
        c.replace(at + 1, c.find('\n', at + 1) - at - 1, key + " = " + value);
    };
    set("horizon", "\"10 us\"");
    set("output_step", "\"2.5e-11 s\"");
    test::write_text(dir + "/big.toml", c);
    const auto sim = test::run_vibroimpact({"simulate", dir + "/big.toml", "--out", dir + "/run"});
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    const std::uintmax_t bytes = fs::file_size(dir + "/run/history.csv");
    std::printf("history.csv: %.1f MB, simulate %.1f s\n", static_cast<double>(bytes) / 1e6, sim.seconds);
    ASSERT_GT(bytes, std::uintmax_t{64} << 20);
    const auto plot = test::run_vibroimpact({"plot", dir + "/run"});
    std::printf("plot: %.1f s\n", plot.seconds);
    EXPECT_EQ(plot.exit_code, 0) << plot.err;
    for (const char* name : {"transient_displacement", "transient_velocity", "transient_force", "transient_energy", "transient_phase"}) {
        const std::string base = dir + "/run/plots/" + std::string(name);
        EXPECT_GT(fs::file_size(base + ".png"), 10000u) << name;
        EXPECT_LT(line_count_of(test::read_text(base + ".csv")), 200000u) << name;
    }
    // The peak contact force of summary.json survives the thinning.
    const std::string summary = test::read_text(dir + "/run/summary.json");
    const std::string force_csv = test::read_text(dir + "/run/plots/transient_force.csv");
    double peak_drawn = 0.0;
    for (std::size_t at = force_csv.find('\n'); at != std::string::npos && at + 1 < force_csv.size(); at = force_csv.find('\n', at + 1)) {
        const std::size_t comma = force_csv.find(',', at + 1);
        peak_drawn = std::max(peak_drawn, std::stod(force_csv.substr(comma + 1, force_csv.find('\n', comma) - comma - 1)));
    }
    const std::string history = test::read_text(dir + "/run/history.csv");
    double peak = 0.0;
    std::size_t column = 0;
    {
        const std::string header = history.substr(0, history.find('\n'));
        std::size_t k = 0;
        for (std::size_t at = 0; at != std::string::npos; at = header.find(',', at + 1), ++k) {
            if (header.compare(at == 0 ? 0 : at + 1, 16, "contact0_force_n") == 0) column = k;
        }
    }
    for (std::size_t at = history.find('\n'); at != std::string::npos && at + 1 < history.size(); at = history.find('\n', at + 1)) {
        std::size_t cell = at + 1;
        for (std::size_t k = 0; k < column; ++k) cell = history.find(',', cell) + 1;
        peak = std::max(peak, std::stod(history.substr(cell, history.find_first_of(",\n", cell) - cell)));
    }
    EXPECT_GT(peak, 0.0);
    EXPECT_EQ(peak_drawn, peak);
    fs::remove_all(dir);
}

// A sweep folder written by hand (plot reads files, not how they were made): a one-axis sweep of
// 50 000 points and a 600 x 600 grid; sweep.json may list `failures` failed points.
void write_sweep_folder(const std::string& dir, const std::vector<std::vector<double>>& axes, std::size_t failures = 0) {
    fs::create_directories(dir);
    std::string json = "{\"axes\": [";
    const char* names[] = {"supports[0].position", "supports[0].stiffness"};
    const char* columns[] = {"supports[0].position_over_l", "supports[0].stiffness_n_m"};
    const char* units[] = {"x/l", "N/m"};
    for (std::size_t a = 0; a < axes.size(); ++a) {
        json += std::string(a ? ", " : "") + "{\"path\": \"" + names[a] + "\", \"column\": \"" + columns[a] + "\", \"unit\": \"" +
                units[a] + "\", \"setting\": \"" + names[a] + "=0:1:" + std::to_string(axes[a].size()) + "\", \"values\": [";
        for (std::size_t i = 0; i < axes[a].size(); ++i) {
            if (i) json += ",";
            append_shortest(json, axes[a][i]);
        }
        json += "]}";
    }
    json += "], \"columns\": [{\"name\": \"z_max\", \"unit\": \"\"}], \"failures\": [";
    // A long list of failed points, as a large sweep's sweep.json holds (plot does not draw them).
    for (std::size_t i = 0; i < failures; ++i) {
        json += std::string(i ? "," : "") + "{\"index\": " + std::to_string(i) +
                ", \"status\": \"error: supports[0].position: must lie in (0, 1] (x0/l), a reason of some length\"}";
    }
    json += "]}\n";
    test::write_text(dir + "/sweep.json", json);
    std::string csv;
    for (std::size_t a = 0; a < axes.size(); ++a) csv += std::string(columns[a]) + ",";
    csv += "z_max,status\n";
    const std::size_t n0 = axes[0].size(), n1 = axes.size() > 1 ? axes[1].size() : 1;
    for (std::size_t i = 0; i < n0; ++i) {
        for (std::size_t k = 0; k < n1; ++k) {
            append_shortest(csv, axes[0][i]);
            csv += ',';
            if (axes.size() > 1) {
                append_shortest(csv, axes[1][k]);
                csv += ',';
            }
            // One point far above the rest: the curve's peak must survive.
            append_shortest(csv, i == 31234 && k == 0 ? 5.0 : std::sin(0.001 * static_cast<double>(i + k)));
            csv += ",ok\n";
        }
    }
    test::write_text(dir + "/sweep.csv", csv);
}

TEST(LargeOutput, PlotDrawsSweepsOfManyPointsFromThinnedCopies) {
    const std::string dir = test::make_temp_dir();
    std::vector<double> x(50000), y(600);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = 0.3 + 0.7 * static_cast<double>(i) / static_cast<double>(x.size() - 1);
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = 100.0 + static_cast<double>(i);
    // Its sweep.json over 64 MiB (the whole-file readers' limit): a million failures listed.
    write_sweep_folder(dir + "/line", {x}, 1000000);
    EXPECT_GT(fs::file_size(dir + "/line/sweep.json"), std::uintmax_t{64} << 20);
    const auto line = test::run_vibroimpact({"plot", dir + "/line"});
    EXPECT_EQ(line.exit_code, 0) << line.err;
    const std::string curve = test::read_text(dir + "/line/plots/sweep_z_max.csv");
    EXPECT_LT(line_count_of(curve), 40002u);
    EXPECT_NE(curve.find(",5\n"), std::string::npos);  // the peak
    EXPECT_NE(test::read_text(dir + "/line/plots/sweep_z_max.svg").find("supports[0].position"), std::string::npos);

    std::vector<double> x600(x.begin(), x.begin() + 600);
    write_sweep_folder(dir + "/map", {x600, y});
    const auto map = test::run_vibroimpact({"plot", dir + "/map"});
    EXPECT_EQ(map.exit_code, 0) << map.err;
    // Every second value of each axis: 300 x 300 cells.
    EXPECT_EQ(line_count_of(test::read_text(dir + "/map/plots/sweep_z_max.csv")), 300u * 300u + 1u);
    EXPECT_GT(fs::file_size(dir + "/map/plots/sweep_z_max.png"), 10000u);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
