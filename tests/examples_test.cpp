// Every case file under examples/ runs: `modes` on each, `simulate` on each that sets a horizon; the
// paper's free impact example keeps the headline numbers its comments and docs quote.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "support/text_checks.hpp"

namespace vi {
namespace {

using test::read_text;
namespace fs = std::filesystem;
using nlohmann::json;
using test::run_vibroimpact;

// Every .toml under examples/, in a stable order.
std::vector<fs::path> example_files() {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(test::source_path("examples"))) {
        if (e.is_regular_file() && e.path().extension() == ".toml") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// A case sets a horizon when a line (not a comment) assigns the key `horizon`.
bool sets_horizon(const std::string& text) {
    return test::assigns_key(text, "horizon");
}

TEST(Examples, EveryCaseFileRuns) {
    const std::vector<fs::path> files = example_files();
    ASSERT_GE(files.size(), 2u) << "examples/ should hold at least the paper's cases";
    int simulated = 0;
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.string());
        const auto modes = run_vibroimpact({"modes", f.string(), "--json"});
        EXPECT_EQ(modes.exit_code, 0) << modes.err;
        EXPECT_TRUE(modes.err.empty()) << modes.err;
        if (modes.exit_code == 0) {
            const json j = json::parse(modes.out, nullptr, false);
            ASSERT_FALSE(j.is_discarded()) << modes.out;
            EXPECT_FALSE(j["unsupported"]["bending"].empty());
        }
        if (!sets_horizon(read_text(f))) continue;
        ++simulated;
        const auto sim = run_vibroimpact({"simulate", f.string(), "--json"});
        EXPECT_EQ(sim.exit_code, 0) << sim.err;
        EXPECT_TRUE(sim.err.empty()) << sim.err;
        if (sim.exit_code == 0) {
            const json j = json::parse(sim.out, nullptr, false);
            ASSERT_FALSE(j.is_discarded()) << sim.out;
            EXPECT_TRUE(j["Tp_reason"].is_string());
        }
    }
    EXPECT_GE(simulated, 1) << "no example sets [solver] horizon";
}

TEST(Examples, FreeImpactTipKeepsItsHeadlineNumbers) {
    const auto r = run_vibroimpact({"simulate", test::source_path("examples/paper/free_impact_tip.toml"), "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json j = json::parse(r.out);
    ASSERT_TRUE(j["T_s"].is_number()) << j["T_s"].dump();
    const double T = j["T_s"].get<double>();
    EXPECT_GT(T, 5.3e-6);
    EXPECT_LT(T, 5.6e-6);
    EXPECT_EQ(j["Tp_reason"], "settled");
    ASSERT_TRUE(j["Tp_s"].is_number());
    EXPECT_LT(j["Tp_s"].get<double>(), 150e-6);  // settles within the horizon
}

// The stiction example (examples/switch/cantilever_stiction.toml): with w = 0.2 J/m^2 it opens again
// after the pulse; `stiction` puts the static boundary at w = 0.370 J/m^2; with w = 2 J/m^2 the
// transient ends stuck, with the force balance in summary.json; a sweep sets the work of adhesion.
TEST(Examples, CantileverStictionReleasesOrSticksWithTheWorkOfAdhesion) {
    const std::string file = test::source_path("examples/switch/cantilever_stiction.toml");
    const auto st = run_vibroimpact({"stiction", file, "--json"});
    ASSERT_EQ(st.exit_code, 0) << st.err;
    const json s = json::parse(st.out);
    EXPECT_EQ(s["supports"][0]["verdict"], "releases");
    EXPECT_NEAR(s["supports"][0]["critical_work_of_adhesion_j_m2"].get<double>(), 0.3703, 1e-4);

    const auto rel = run_vibroimpact({"simulate", file, "--json"});
    ASSERT_EQ(rel.exit_code, 0) << rel.err;
    EXPECT_EQ(json::parse(rel.out)["switching"]["state"], "released");

    const std::string dir = (fs::temp_directory_path() / ("vi_stiction_" + std::to_string(::getpid()))).string();
    fs::create_directories(dir);
    std::string text = read_text(file);
    const std::string from = "work_of_adhesion = \"0.2 J/m^2\"";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "work_of_adhesion = \"2 J/m^2\"");
    test::write_text(dir + "/stuck.toml", text);
    const auto stuck = run_vibroimpact({"simulate", dir + "/stuck.toml", "--json"});
    ASSERT_EQ(stuck.exit_code, 0) << stuck.err;
    const json sw = json::parse(stuck.out)["switching"];
    EXPECT_EQ(sw["state"], "stuck");
    EXPECT_NEAR(sw["stuck"]["restoring_force_n"].get<double>(), 1.163e-5, 1e-8);
    EXPECT_NEAR(sw["stuck"]["pull_off_force_n"].get<double>(), 2.0 * 3.141592653589793 * 5e-6 * 2.0, 1e-12);

    const auto sweep = run_vibroimpact(
        {"sweep", file, "--set", "supports[0].work_of_adhesion=0.5:2:2", "--out", dir + "/sweep", "--threads", "1"});
    EXPECT_EQ(sweep.exit_code, 0) << sweep.err;
    const std::string csv = read_text(dir + "/sweep/sweep.csv");
    EXPECT_NE(csv.find("supports[0].work_of_adhesion"), std::string::npos);
    fs::remove_all(dir);
}

// The capacitive switch that sticks on its adhesive nitride (examples/switch/capacitive_stiction.toml):
// `stiction` gives the peel balance (it sticks above w = 0.0430 J/m^2, lying flat from l_d = 94.7 um
// on) and the FE beam settled on the layer; with w = 0.1 J/m^2 the transient ends stuck with the
// peel balance in summary.json (run here to 8 us, 4 us after the voltage fell); with 0.02 J/m^2 it lets go.
TEST(Examples, CapacitiveStictionSticksOrLetsGoWithTheWorkOfAdhesion) {
    const std::string file = test::source_path("examples/switch/capacitive_stiction.toml");
    const auto st = run_vibroimpact({"stiction", file, "--json", "--elements", "100"});
    ASSERT_EQ(st.exit_code, 0) << st.err;
    const json layer = json::parse(st.out)["layers"][0];
    EXPECT_EQ(layer["verdict"], "sticks");
    EXPECT_NEAR(layer["critical_work_of_adhesion_j_m2"].get<double>(), 0.04295, 1e-5);
    EXPECT_NEAR(layer["contact_from_m"].get<double>(), 94.716e-6, 1e-9);
    EXPECT_TRUE(layer["settled"]["stuck"].get<bool>());
    // The FE front on 100 elements against the layer's semi-analytic solution (docs/adhesion.md §8).
    EXPECT_NEAR(layer["detached_length_fe_m"].get<double>() / layer["detached_length_on_layer_m"].get<double>(), 1.0, 1e-3);

    const std::string dir = (fs::temp_directory_path() / ("vi_capacitive_" + std::to_string(::getpid()))).string();
    fs::create_directories(dir);
    const std::string text = read_text(file);
    const auto variant = [&](const std::string& name, const std::string& from, const std::string& to) {
        std::string t = text;
        EXPECT_NE(t.find(from), std::string::npos) << from;
        if (t.find(from) != std::string::npos) t.replace(t.find(from), from.size(), to);
        test::write_text(dir + "/" + name, t);
        return dir + "/" + name;
    };
    const auto stuck = run_vibroimpact({"simulate", variant("stuck.toml", "horizon = \"20 us\"", "horizon = \"8 us\""), "--json"});
    ASSERT_EQ(stuck.exit_code, 0) << stuck.err;
    const json sw = json::parse(stuck.out)["switching"];
    EXPECT_EQ(sw["state"], "stuck");
    EXPECT_EQ(sw["stuck"]["contact"], "electrodes[0].dielectric");
    EXPECT_NEAR(sw["stuck"]["restoring_force_n"].get<double>(), 1.052e-4, 1e-7);
    EXPECT_LT(sw["stuck"]["contact_force_n"].get<double>(), 0.0);
    EXPECT_NEAR(sw["stuck"]["adhesion_energy_j_m"].get<double>(), 0.1 * 30e-6, 1e-15);
    EXPECT_NE(sw["reason"].get<std::string>().find("peels back and stays down"), std::string::npos) << sw["reason"];

    const auto free =
        run_vibroimpact({"simulate", variant("free.toml", "work_of_adhesion = \"0.1 J/m^2\"", "work_of_adhesion = \"0.02 J/m^2\""), "--json"});
    ASSERT_EQ(free.exit_code, 0) << free.err;
    const json fw = json::parse(free.out)["switching"];
    EXPECT_EQ(fw["state"], "released");
    ASSERT_TRUE(fw["release_time_s"].is_number());
    EXPECT_GT(fw["release_time_s"].get<double>(), 4e-6);  // after the voltage fell
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
