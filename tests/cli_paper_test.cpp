// The `paper` command end to end on a coarse study: every file of the folder, the report embedding
// every figure and the claims table, the claims' numbers against closed forms and against the CSVs
// they come from, gaps where T_p is not reached, and errors that leave nothing behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/csv_reader.hpp"
#include "validation/closed_forms.hpp"
#include "support/csv_checks.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

using test::read_text;
namespace fs = std::filesystem;
using nlohmann::json;

// A CSV as a header and rows of cells.
struct Csv {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    [[nodiscard]] std::size_t col(const std::string& name) const {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return static_cast<std::size_t>(it - header.begin());
    }
};

Csv read_csv(const fs::path& p) {
    Csv c;
    for (CsvRow& row : split_csv(read_text(p), p.string())) {
        if (c.header.empty()) c.header = std::move(row.cells);
        else c.rows.push_back(std::move(row.cells));
    }
    return c;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
    return n;
}

// One coarse run of the whole study for the suite (a few seconds; the default resolution is for the report).
class CliPaper : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new fs::path(fs::path(test::make_temp_dir()) / "paper");
        // A scan horizon of 150 us leaves the positions near the clamp unsettled, so the gaps are tested too.
        result_ = new test::CommandResult(test::run_vibroimpact({"paper", "--out", dir_->string(), "--positions", "8",
                                                                 "--modal-positions", "20", "--prestress-points", "6",
                                                                 "--scan-horizon", "150 us", "--quiet"}));
    }
    static void TearDownTestSuite() {
        fs::remove_all(dir_->parent_path());
        delete dir_;
        delete result_;
    }
    static const fs::path& dir() { return *dir_; }
    static const test::CommandResult& result() { return *result_; }
    static json claims() { return json::parse(read_text(dir() / "claims.json")); }
    static json claim(const std::string& id) {
        for (const json& c : claims()) {
            if (c["id"] == id) return c;
        }
        ADD_FAILURE() << "no claim " << id;
        return json::object();
    }

    // The checks, run by two tests (each test is a process of its own under CTest, and each runs the study).
    static void check_files();
    static void check_report();
    static void check_modal_claims();
    static void check_transient_claims();
    static void check_gaps();

private:
    static fs::path* dir_;
    static test::CommandResult* result_;
};

fs::path* CliPaper::dir_ = nullptr;
test::CommandResult* CliPaper::result_ = nullptr;

void CliPaper::check_files() {
    EXPECT_TRUE(result().err.empty()) << result().err;
    EXPECT_NE(result().out.find("report.html"), std::string::npos);
    for (int n = 2; n <= 11; ++n) {
        const std::string stem = "fig" + std::to_string(n);
        for (const char* ext : {".png", ".svg", ".csv", ".gp"}) {
            const fs::path p = dir() / (stem + ext);
            ASSERT_TRUE(fs::is_regular_file(p)) << p;
            EXPECT_GT(fs::file_size(p), 100u) << p;
        }
        EXPECT_EQ(read_text(dir() / (stem + ".png")).substr(1, 3), "PNG") << stem;
        EXPECT_NE(read_text(dir() / (stem + ".svg")).find("<svg"), std::string::npos) << stem;
        const Csv csv = read_csv(dir() / (stem + ".csv"));
        EXPECT_FALSE(csv.header.empty()) << stem;
        EXPECT_FALSE(csv.rows.empty()) << stem;
    }
    for (const char* extra : {"fig2_points.csv", "fig3_impacts.csv", "fig7_lines.csv", "report.html", "report.md", "claims.json"}) {
        EXPECT_TRUE(fs::is_regular_file(dir() / extra)) << extra;
    }
    // Every CSV follows the one convention: each column names its unit or is dimensionless by its
    // name, numbers in their shortest round-trip form, "nan" where a run gives no value.
    EXPECT_EQ(test::expect_csv_convention_in(dir().string()), 13u);
    // Nothing but those: no temporary or partial files left behind.
    for (const auto& e : fs::directory_iterator(dir())) EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
}

void CliPaper::check_report() {
    const std::string html = read_text(dir() / "report.html");
    EXPECT_EQ(count(html, "src=\"data:image/png;base64,"), 10u);
    for (int n = 2; n <= 11; ++n) EXPECT_NE(html.find("<h3>Fig. " + std::to_string(n) + ":"), std::string::npos) << n;
    // Self-contained: nothing to fetch, from the network or from beside the file, to render the page.
    EXPECT_EQ(count(html, "src=\"http"), 0u);
    EXPECT_EQ(count(html, "<link"), 0u);
    // Scripts only inline: each figure's chart data, the page script and the vendored uPlot.
    EXPECT_EQ(count(html, "<script src"), 0u);
    EXPECT_EQ(count(html, "<script type=\"application/json\" class=\"vi-chart-data\">"), 10u);
    // The animated beam's data (the typical transient's field).
    EXPECT_EQ(count(html, "<script type=\"application/json\" class=\"vi-animation-data\">"), 1u);
    EXPECT_EQ(count(html, "<figure id=\"beam\" class=\"vi-animation\">"), 1u);
    EXPECT_EQ(count(html, "<script"), 13u);
    EXPECT_EQ(count(html, "src=\"") , count(html, "src=\"data:"));
    const json c = claims();
    ASSERT_GE(c.size(), 15u);
    EXPECT_NE(html.find("<th>the paper</th>"), std::string::npos);
    for (const json& claim : c) {
        EXPECT_FALSE(claim["id"].get<std::string>().empty());
        const std::string v = claim["verdict"];
        EXPECT_TRUE(v == "agrees" || v == "partly" || v == "disagrees" || v == "not computed") << v;
    }
    for (const char* section : {"id=\"claims\"", "id=\"parameters\"", "id=\"timing\"", "id=\"run\""}) {
        EXPECT_NE(html.find(section), std::string::npos) << section;
    }
    const std::string md = read_text(dir() / "report.md");
    for (int n = 2; n <= 11; ++n) EXPECT_NE(md.find("(fig" + std::to_string(n) + ".png)"), std::string::npos) << n;
    EXPECT_NE(md.find("| # | where | the paper | this run | verdict | note |"), std::string::npos);
}

void CliPaper::check_modal_claims() {
    const std::vector<double> beta = closed_form::cantilever_beta_l(3);
    const double node2 = closed_form::cantilever_shape_zeros(beta[1]).at(0);
    const double node3 = closed_form::cantilever_shape_zeros(beta[2]).at(1);
    EXPECT_NEAR(node2, 0.7834, 1e-4);
    EXPECT_NEAR(node3, 0.8677, 1e-4);
    EXPECT_NEAR(claim("nodal_point_mode2")["values"]["x_over_l"].get<double>(), node2, 1e-4);
    EXPECT_NEAR(claim("nodal_point_mode3")["values"]["x_over_l"].get<double>(), node3, 1e-4);
    EXPECT_EQ(claim("nodal_point_mode2")["verdict"], "agrees");
    // The first supported frequency peaks at mode 2's nodal point, where it equals omega_2 / omega_1.
    const json peak = claim("ratio1_peak")["values"];
    EXPECT_NEAR(peak["x0_over_l"].get<double>(), node2, 1e-4);
    EXPECT_NEAR(peak["ratio"].get<double>(), std::pow(beta[1] / beta[0], 2), 1e-4);
    EXPECT_NEAR(claim("omega3_over_omega1")["values"]["ratio"].get<double>(), std::pow(beta[2] / beta[0], 2), 5e-3);
    EXPECT_NEAR(claim("peak_mode3")["values"]["x_over_l"].get<double>(), 0.6923, 1e-4);
    // Fig. 8's CSV: no sampled ratio above the refined maximum, and the best sample next to it.
    const Csv f8 = read_csv(dir() / "fig8.csv");
    double best = 0.0, best_x = 0.0;
    for (const auto& r : f8.rows) {
        const double v = std::stod(r[f8.col("ratio_1")]);
        if (v > best) {
            best = v;
            best_x = std::stod(r[f8.col("x0_over_l")]);
        }
    }
    EXPECT_LE(best, peak["ratio"].get<double>() + 1e-9);
    EXPECT_NEAR(best_x, peak["x0_over_l"].get<double>(), 1.0 / 20 + 1e-9);
}

void CliPaper::check_transient_claims() {
    const Csv f4 = read_csv(dir() / "fig4.csv");
    const Csv f5 = read_csv(dir() / "fig5.csv");
    auto row_at = [](const Csv& c, double x) -> const std::vector<std::string>& {
        for (const auto& r : c.rows) {
            if (std::abs(std::stod(r[0]) - x) < 1e-9) return r;
        }
        ADD_FAILURE() << "no row at x0/l = " << x;
        return c.rows.front();
    };
    const json v87 = claim("rebound_min_087")["values"];
    ASSERT_TRUE(v87.contains("z_max_at_point"));
    EXPECT_NEAR(v87["z_max_at_point"].get<double>(), std::stod(row_at(f4, 0.87)[f4.col("m50_z_max")]),
                1e-8 * v87["z_max_at_point"].get<double>());
    const json t87 = claim("shorter_transient_87")["values"];
    const std::string cell = row_at(f5, 0.87)[f5.col("m50_tau_p")];
    if (t87.contains("tau_p_at_point")) {
        EXPECT_NEAR(t87["tau_p_at_point"].get<double>(), std::stod(cell), 1e-8 * std::stod(cell));
    } else {
        EXPECT_EQ(cell, "nan");
    }
    // T of Fig. 3: the first two impact onsets of fig3_impacts.csv.
    const Csv im = read_csv(dir() / "fig3_impacts.csv");
    ASSERT_GE(im.rows.size(), 2u);
    const double T = (std::stod(im.rows[1][im.col("t_on_us")]) - std::stod(im.rows[0][im.col("t_on_us")])) * 1e-6;
    EXPECT_NEAR(claim("period_T")["values"]["T_s"].get<double>(), T, 1e-8 * T);
    EXPECT_NEAR(T, 5.4497e-6, 1e-9);  // docs/validation.md, section 7
    EXPECT_EQ(claim("period_T")["verdict"], "disagrees");
}

void CliPaper::check_gaps() {
    const Csv f5 = read_csv(dir() / "fig5.csv");
    int unsettled = 0;
    for (const auto& r : f5.rows) {
        const std::string reason = r[f5.col("m50_tp_reason")];
        const std::string tau_p = r[f5.col("m50_tau_p")];
        EXPECT_EQ(reason == "settled" || reason == "persistent_contact", tau_p != "nan") << reason << " " << tau_p;
        unsettled += tau_p == "nan";
    }
    EXPECT_GT(unsettled, 0);  // the scan starts at 0.3, where the bouncing outlasts a 150 us horizon
    EXPECT_EQ(claim("shorter_transient_87")["values"]["unsettled_positions"].get<int>(), unsettled);
    EXPECT_NE(read_text(dir() / "report.html").find(std::to_string(unsettled) + " of " + std::to_string(f5.rows.size()) +
                                                     " positions did not settle"),
              std::string::npos);
}

TEST_F(CliPaper, WritesEveryFileAndAReportThatEmbedsThem) {
    ASSERT_EQ(result().exit_code, 0) << result().err;
    check_files();
    check_report();
}

TEST_F(CliPaper, ClaimsMatchClosedFormsAndTheCsvs) {
    ASSERT_EQ(result().exit_code, 0) << result().err;
    check_modal_claims();
    check_transient_claims();
    check_gaps();
}

TEST(CliPaperErrors, MissingGnuplotFailsBeforeAnything) {
    const fs::path tmp = test::make_temp_dir();
    const fs::path out = tmp / "paper";
    const auto r = test::run_vibroimpact({"paper", "--out", out.string(), "--gnuplot", (tmp / "no-gnuplot").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("gnuplot"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(tmp);
}

TEST(CliPaperErrors, UnusableOutputFolderFailsAndLeavesNothing) {
    const fs::path tmp = test::make_temp_dir();
    const fs::path file = tmp / "a-file";
    std::ofstream(file) << "x";
    for (const fs::path& out : {file, file / "paper"}) {
        const auto r = test::run_vibroimpact({"paper", "--out", out.string()});
        EXPECT_EQ(r.exit_code, 1) << out;
        EXPECT_NE(r.err.find(out.string()), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_EQ(read_text(file), "x");
    // A folder that does not exist yet is made and removed again by the check, not left empty.
    const fs::path fresh = tmp / "new" / "deeper";
    const auto r = test::run_vibroimpact({"paper", "--out", fresh.string(), "--gnuplot", (tmp / "no-gnuplot").string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_FALSE(fs::exists(tmp / "new"));
    fs::remove_all(tmp);
}

TEST(CliPaperErrors, BadCaseInExamplesFolderIsBadInputWithFileAndLine) {
    const fs::path tmp = test::make_temp_dir();
    for (const char* f : {"cantilever.toml", "free_impact_tip.toml", "free_impact_prestress.toml"}) {
        fs::copy_file(test::source_path(std::string("examples/paper/") + f), tmp / f);
    }
    std::string text = read_text(tmp / "free_impact_tip.toml");
    const auto pos = text.find("stiffness = \"1000 N/m\"");
    ASSERT_NE(pos, std::string::npos);
    text.replace(pos, 22, "stiffness = \"1000 N\"");
    std::ofstream(tmp / "free_impact_tip.toml") << text;
    const auto r = test::run_vibroimpact({"paper", "--out", (tmp / "out").string(), "--examples", tmp.string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("free_impact_tip.toml:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("stiffness"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp / "out"));
    const auto bad = test::run_vibroimpact({"paper", "--positions", "1"});
    EXPECT_EQ(bad.exit_code, 2);
    for (const char* horizon : {"5 m", "-1 us", "0 us", "soon"}) {
        const auto h = test::run_vibroimpact({"paper", "--out", (tmp / "out").string(), "--scan-horizon", horizon});
        EXPECT_EQ(h.exit_code, 2) << horizon;
        EXPECT_NE(h.err.find("--scan-horizon"), std::string::npos) << h.err;
        EXPECT_FALSE(fs::exists(tmp / "out")) << horizon;
    }
    fs::remove_all(tmp);
}

// With --examples the report says whose choice the unstated parameters are: the case files', not
// the paper's and not ours.
TEST(CliPaperExamples, ValuesAreLabelledAsTheFilesChoice) {
    const fs::path tmp = test::make_temp_dir();
    for (const char* f : {"cantilever.toml", "free_impact_tip.toml", "free_impact_prestress.toml"}) {
        fs::copy_file(test::source_path(std::string("examples/paper/") + f), tmp / f);
    }
    std::string text = read_text(tmp / "free_impact_tip.toml");
    const auto pos = text.find("stiffness = \"1000 N/m\"");
    ASSERT_NE(pos, std::string::npos);
    text.replace(pos, 22, "stiffness = \"2000 N/m\"");
    std::ofstream(tmp / "free_impact_tip.toml") << text;
    const auto r = test::run_vibroimpact({"paper", "--out", (tmp / "out").string(), "--examples", tmp.string(), "--positions",
                                          "3", "--modal-positions", "3", "--prestress-points", "3", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string report = read_text(tmp / "out" / "report.md");
    EXPECT_NE(report.find("The values used are those chosen in the case files of " + tmp.string()), std::string::npos);
    EXPECT_NE(report.find("| contact stiffness Kc | 2000 N/m |"), std::string::npos);
    EXPECT_EQ(report.find("The values used are our choice"), std::string::npos);
    fs::remove_all(tmp);
}

}  // namespace
}  // namespace vi
