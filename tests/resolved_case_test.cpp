// The resolved case is a case file: summary.json's resolved.case, and case_to_toml of the case read,
// each written out as TOML and simulated again, give the run of the original bit for bit (history.csv,
// events.csv and summary.json byte for byte), for every example with a horizon and every file of
// tests/cases.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "io/case_reader.hpp"
#include "io/case_writer.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

toml::table toml_of(const nlohmann::json& object);

// One JSON value as TOML: objects as tables, arrays of objects as arrays of tables.
void insert_toml(toml::table& t, const std::string& key, const nlohmann::json& v) {
    if (v.is_object()) {
        t.insert(key, toml_of(v));
    } else if (v.is_array()) {
        toml::array a;
        for (const nlohmann::json& e : v) {
            if (e.is_object()) {
                a.push_back(toml_of(e));
            } else if (e.is_number_integer()) {
                a.push_back(e.get<std::int64_t>());
            } else {
                a.push_back(e.get<double>());
            }
        }
        t.insert(key, std::move(a));
    } else if (v.is_boolean()) {
        t.insert(key, v.get<bool>());
    } else if (v.is_number_integer()) {
        t.insert(key, v.get<std::int64_t>());
    } else if (v.is_number()) {
        t.insert(key, v.get<double>());
    } else {
        t.insert(key, v.get<std::string>());
    }
}

toml::table toml_of(const nlohmann::json& object) {
    toml::table t;
    for (const auto& [key, value] : object.items()) insert_toml(t, key, value);
    return t;
}

// Every case the test runs: the examples and the files of tests/cases that set a horizon (a case
// for pullin, whose transients take their own, has none).
std::vector<std::string> transient_cases() {
    std::vector<std::string> out;
    const auto add_transients = [&](const fs::path& folder) {
        for (const auto& f : fs::directory_iterator(folder)) {
            if (f.path().extension() != ".toml") continue;
            if (read_case_file(f.path().string()).solver.horizon > 0.0) out.push_back(f.path().string());
        }
    };
    for (const auto& dir : fs::directory_iterator(test::source_path("examples"))) {
        if (dir.is_directory()) add_transients(dir.path());
    }
    add_transients(test::source_path("tests/cases"));
    std::sort(out.begin(), out.end());
    return out;
}

// simulate `path` --out `out`; the run must succeed.
void simulate(const std::string& path, const std::string& out) {
    const auto r = test::run_vibroimpact({"simulate", path, "--out", out});
    ASSERT_EQ(r.exit_code, 0) << path << ": " << r.err;
}

void expect_same_run(const std::string& a, const std::string& b, const std::string& what) {
    for (const char* file : {"history.csv", "events.csv", "summary.json"}) {
        const std::string x = test::read_text(a + "/" + file), y = test::read_text(b + "/" + file);
        EXPECT_FALSE(x.empty()) << what << ": " << file;
        EXPECT_TRUE(x == y) << what << ": " << file << " differs from the original run's";
    }
}

TEST(ResolvedCase, ReadBackAsACaseFileItRunsBitForBitTheSame) {
    const std::vector<std::string> cases = transient_cases();
    ASSERT_GE(cases.size(), 15u);
    const std::string dir = test::make_temp_dir();
    int k = 0;
    for (const std::string& path : cases) {
        SCOPED_TRACE(path);
        const std::string run = dir + "/run" + std::to_string(k);
        simulate(path, run + "/original");
        const nlohmann::json summary = nlohmann::json::parse(test::read_text(run + "/original/summary.json"));
        ASSERT_TRUE(summary["resolved"].contains("case"));

        // summary.json's resolved case, written as TOML.
        std::ostringstream from_summary;
        from_summary << toml_of(summary["resolved"]["case"]);
        test::write_text(run + "/resolved.toml", from_summary.str());
        simulate(run + "/resolved.toml", run + "/resolved");
        expect_same_run(run + "/original", run + "/resolved", "resolved.case of summary.json");

        // case_to_toml of the case as read (keys left to their defaults stay out).
        test::write_text(run + "/written.toml", case_to_toml(read_case_file(path)));
        simulate(run + "/written.toml", run + "/written");
        expect_same_run(run + "/original", run + "/written", "case_to_toml");
        ++k;
    }
    fs::remove_all(dir);
}

// What resolved.case holds for the switch in air: the electrodes, the air and the keys a case file
// left to their defaults, with the values the run used.
TEST(ResolvedCase, HoldsEverySectionWithTheValuesTheRunUsed) {
    const std::string dir = test::make_temp_dir();
    simulate(test::source_path("examples/switch/cantilever_switch_air.toml"), dir + "/out");
    const nlohmann::json j = nlohmann::json::parse(test::read_text(dir + "/out/summary.json"));
    const nlohmann::json& c = j["resolved"]["case"];
    EXPECT_EQ(c["beam"]["length"], 117e-6);
    EXPECT_EQ(c["beam"]["stretching"], false);
    EXPECT_EQ(c["electrodes"][0]["waveform"], "step");
    EXPECT_EQ(c["electrodes"][0]["voltage"], 70.0);
    EXPECT_EQ(c["electrodes"][0]["width"], c["beam"]["width"]);
    EXPECT_EQ(c["air"]["mean_free_path"], j["resolved"]["air"]["mean_free_path_m"]);
    EXPECT_EQ(c["solver"]["group_gap"], j["resolved"]["solver"]["group_gap_s"]);
    EXPECT_EQ(c["solver"]["output_step"], j["resolved"]["solver"]["output_step_s"]);
    EXPECT_EQ(c["supports"][0]["adhesion"], "none");
    EXPECT_FALSE(c["supports"][0].contains("work_of_adhesion"));
    fs::remove_all(dir);
}

// A table file is written by its absolute path, so the written case reads the same rows from any
// folder (and from summary.json, wherever the run's output went).
TEST(ResolvedCase, TableFilesAreNamedSoThatTheyReadFromAnywhere) {
    const std::string dir = test::make_temp_dir();
    fs::create_directories(dir + "/case/tables");
    fs::create_directories(dir + "/elsewhere");
    test::write_text(dir + "/case/tables/pulse.csv", "t_s,g\n0,0\n1e-6,1\n2e-6,0\n");
    test::write_text(dir + "/case/tables/drive.csv", "t_s,V_V\n0,0\n1e-6,3\n");
    const std::string text = test::read_text(test::source_path("examples/paper/free_impact_tip.toml")) +
                             "\n[[loads]]\nposition = 0.5\namplitude = \"1 uN\"\nkind = \"table\"\ntable = \"tables/pulse.csv\"\n"
                             "[[electrodes]]\nfrom = 0.2\nto = 0.6\ngap = \"3 um\"\nwaveform = \"table\"\ntable = \"tables/drive.csv\"\n";
    test::write_text(dir + "/case/case.toml", text);
    const Case c = read_case_file(dir + "/case/case.toml");
    test::write_text(dir + "/elsewhere/written.toml", case_to_toml(c));
    const Case back = read_case_file(dir + "/elsewhere/written.toml");
    EXPECT_EQ(back.loads[0].time.times, c.loads[0].time.times);
    EXPECT_EQ(back.loads[0].time.values, c.loads[0].time.values);
    EXPECT_EQ(back.electrodes[0].time.values, (std::vector<double>{0.0, 3.0}));
    EXPECT_TRUE(fs::path(back.loads[0].table_file).is_absolute()) << back.loads[0].table_file;
    EXPECT_EQ(case_to_json(back)["electrodes"][0]["table"], fs::weakly_canonical(dir + "/case/tables/drive.csv").string());
    EXPECT_FALSE(case_to_json(back)["electrodes"][0].contains("voltage"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
