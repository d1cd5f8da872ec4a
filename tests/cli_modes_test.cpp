// The `modes` and `support-scan` commands end to end: output, JSON schema, bad input handling.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_command.hpp"
#include "support/text_checks.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using test::run_vibroimpact;

const std::string kGood = R"(name = "cli"
[beam]
length = "117 um"
width = "30 um"
thickness = "2 um"
elements = 50
[material]
youngs_modulus = "207 GPa"
density = "8902 kg/m^3"
poisson_ratio = 0.31
[[supports]]
position = 1.0
stiffness = "50 N/m"
)";

std::string write_case(const std::string& dir, const std::string& text) {
    const std::string path = dir + "/bad.toml";
    std::ofstream(path) << text;
    return path;
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
    return text;
}

TEST(CliModes, JsonHasTheStableSchema) {
    const auto r = run_vibroimpact({"modes", test::source_path("examples/paper/cantilever.toml"), "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["case_name"], "paper-cantilever");
    EXPECT_EQ(j["dofs"].get<int>(), 150);
    const auto& b = j["unsupported"]["bending"];
    ASSERT_EQ(b.size(), 5u);
    for (const char* key : {"mode", "frequency_hz", "omega_rad_s", "nodes", "rotation_nodes", "peaks", "rotation_peaks"}) {
        EXPECT_TRUE(b[0].contains(key)) << key;
    }
    EXPECT_TRUE(b[2]["peaks"][0].contains("x"));
    EXPECT_TRUE(b[2]["peaks"][0].contains("amplitude"));
    EXPECT_NEAR(b[1]["nodes"][0].get<double>(), 0.7834, 1e-4);
    EXPECT_FALSE(j["unsupported"]["axial"].empty());
    EXPECT_EQ(j["supported"]["bending"].size(), 5u);
    EXPECT_EQ(j["supported"]["ratios"].size(), 5u);
    EXPECT_NEAR(j["supported"]["ratios"][0].get<double>(), std::pow(3.926602 / 1.875104, 2), 1e-5);
}

TEST(CliModes, OutFolderGetsJsonAndCsv) {
    const std::string dir = test::make_temp_dir() + "/out";
    const auto r = run_vibroimpact({"modes", test::source_path("examples/paper/cantilever.toml"), "--out", dir});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* f : {"modes.json", "frequencies.csv", "shapes_unsupported.csv", "shapes_supported.csv"}) {
        EXPECT_TRUE(fs::exists(dir + "/" + f)) << f;
    }
    std::ifstream in(dir + "/shapes_unsupported.csv");
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header.rfind("x_over_l,x_m,v_1_per_sqrt_kg,theta_1_per_m_sqrt_kg,v_2_per_sqrt_kg", 0), 0u) << header;
    fs::remove_all(fs::path(dir).parent_path());
}

TEST(CliModes, SpringSupportModelIsSelectable) {
    const auto r = run_vibroimpact(
        {"modes", test::source_path("examples/paper/cantilever.toml"), "--json", "--support-model", "spring"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["supported"]["support_model"], "spring");
    EXPECT_LT(j["supported"]["ratios"][0].get<double>(), std::pow(3.926602 / 1.875104, 2));
}

struct BadCase {
    const char* what;
    std::string text;
    const char* expected_prefix;  // "bad.toml:LINE: KEY:"
};

TEST(CliModes, EveryBadInputGivesOneLineExitTwoAndWritesNothing) {
    const std::vector<BadCase> cases = {
        {"unknown key", replace(kGood, "elements = 50", "elements = 50\ncolour = 1"), "bad.toml:7: beam.colour:"},
        {"missing key", replace(kGood, "width = \"30 um\"\n", ""), "bad.toml:2: beam.width:"},
        {"wrong type", replace(kGood, "elements = 50", "elements = \"many\""), "bad.toml:6: beam.elements:"},
        {"bad unit", replace(kGood, "\"117 um\"", "\"117 furlongs\""), "bad.toml:3: beam.length:"},
        {"zero length", replace(kGood, "\"117 um\"", "0"), "bad.toml:3: beam.length:"},
        {"negative thickness", replace(kGood, "\"2 um\"", "\"-2 um\""), "bad.toml:5: beam.thickness:"},
        {"zero density", replace(kGood, "\"8902 kg/m^3\"", "0"), "bad.toml:9: material.density:"},
        {"negative modulus", replace(kGood, "\"207 GPa\"", "-1"), "bad.toml:8: material.youngs_modulus:"},
        {"no elements", replace(kGood, "elements = 50", "elements = 0"), "bad.toml:6: beam.elements:"},
        {"support outside", replace(kGood, "position = 1.0", "position = 1.2"), "bad.toml:12: supports[0].position:"},
        {"support at zero", replace(kGood, "position = 1.0", "position = 0"), "bad.toml:12: supports[0].position:"},
        {"two supports one place", kGood + "[[supports]]\nposition = 1.0\nstiffness = \"5 N/m\"\n",
         "bad.toml:15: supports[1].position:"},
        {"nan", replace(kGood, "poisson_ratio = 0.31", "poisson_ratio = nan"), "bad.toml:10: material.poisson_ratio:"},
        {"infinity", replace(kGood, "\"117 um\"", "inf"), "bad.toml:3: beam.length:"},
        {"free-free", replace(kGood, "elements = 50", "elements = 50\nleft = \"free\"\nright = \"free\""),
         "bad.toml:8: beam.right:"},
    };
    for (const BadCase& c : cases) {
        const std::string dir = test::make_temp_dir();
        const std::string path = write_case(dir, c.text);
        const std::string out = dir + "/out";
        const auto r = run_vibroimpact({"modes", path, "--out", out});
        EXPECT_EQ(r.exit_code, 2) << c.what;
        EXPECT_TRUE(test::is_one_error_line(r.err)) << c.what << ": " << r.err;
        EXPECT_NE(r.err.find(dir + "/" + c.expected_prefix), std::string::npos) << c.what << ": " << r.err;
        EXPECT_TRUE(r.out.empty()) << c.what;
        EXPECT_FALSE(fs::exists(out)) << c.what << " wrote output";
        fs::remove_all(dir);
    }
}

TEST(CliModes, MissingFileAndBadOptionsExitTwo) {
    auto r = run_vibroimpact({"modes", "/nonexistent/case.toml"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("/nonexistent/case.toml"), std::string::npos);
    r = run_vibroimpact({"modes", test::source_path("examples/paper/cantilever.toml"), "--count", "0"});
    EXPECT_EQ(r.exit_code, 2);
    r = run_vibroimpact({"modes", test::source_path("examples/paper/cantilever.toml"), "--support-model", "glue"});
    EXPECT_EQ(r.exit_code, 2);
    r = run_vibroimpact({});
    EXPECT_EQ(r.exit_code, 2);
}

TEST(CliModes, HelpOnEverySubcommand) {
    for (const char* sub : {"modes", "support-scan"}) {
        const auto r = run_vibroimpact({sub, "--help"});
        EXPECT_EQ(r.exit_code, 0) << sub;
        EXPECT_NE(r.out.find("--out"), std::string::npos) << sub;
    }
}

TEST(CliSupportScan, WritesTheFigure8Curve) {
    const std::string dir = test::make_temp_dir();
    const auto r = run_vibroimpact({"support-scan", test::source_path("examples/paper/cantilever.toml"),
                                    "--positions", "0.7,0.78,0.86", "--out", dir + "/scan"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(dir + "/scan/support_scan.csv");
    std::string header, row;
    std::getline(in, header);
    EXPECT_EQ(header, "x0_over_l,ratio_1,ratio_2,ratio_3,f_supported_1_hz,f_supported_2_hz,f_supported_3_hz");
    int rows = 0;
    while (std::getline(in, row)) ++rows;
    EXPECT_EQ(rows, 3);
    fs::remove_all(dir);
}

TEST(CliSupportScan, BadPositionsExitTwo) {
    for (const char* spec : {"", "0.5:1:0", "a,b", "0:1:5", "0.5:2:3"}) {
        const auto r = run_vibroimpact(
            {"support-scan", test::source_path("examples/paper/cantilever.toml"), "--positions", spec});
        EXPECT_EQ(r.exit_code, 2) << spec << ": " << r.err;
        EXPECT_NE(r.err.find("--positions"), std::string::npos) << spec;
    }
}

}  // namespace
}  // namespace vi
