// `vibroimpact new KIND`: every kind writes its example case (with one header line) and the
// written case runs; an existing file is kept unless --force, and an unknown kind is bad input.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

struct Kind {
    const char* kind;
    const char* example;
};

TEST(CliNew, EveryKindWritesItsExampleAndTheCaseRuns) {
    const std::string dir = test::make_temp_dir();
    for (const Kind& k : {Kind{"cantilever", "examples/paper/free_impact_tip.toml"},
                          Kind{"bridge", "examples/devices/bridge_relay.toml"},
                          Kind{"impact-sensor", "examples/devices/impact_sensor.toml"},
                          Kind{"cantilever-switch", "examples/switch/cantilever_switch.toml"},
                          Kind{"bridge-switch", "examples/switch/bridge_switch.toml"}}) {
        SCOPED_TRACE(k.kind);
        const std::string file = dir + "/" + k.kind + ".toml";
        const auto w = test::run_vibroimpact({"new", k.kind, "--out", file});
        ASSERT_EQ(w.exit_code, 0) << w.err;
        const std::string text = test::read_text(file);
        const std::string example = test::read_text(test::source_path(k.example));
        ASSERT_GT(text.size(), example.size());
        EXPECT_EQ(text.substr(text.size() - example.size()), example);
        EXPECT_EQ(text.rfind("# Written by `vibroimpact new ", 0), 0u);
        const auto printed = test::run_vibroimpact({"new", k.kind});
        EXPECT_EQ(printed.out, text);
        const auto run = test::run_vibroimpact({"simulate", file, "--out", dir + "/" + k.kind});
        EXPECT_EQ(run.exit_code, 0) << run.err;
    }
    fs::remove_all(dir);
}

TEST(CliNew, AnExistingFileIsKeptUnlessForceAndAnUnknownKindIsBadInput) {
    const std::string dir = test::make_temp_dir();
    const std::string file = dir + "/mine.toml";
    test::write_text(file, "keep me\n");
    const auto kept = test::run_vibroimpact({"new", "bridge", "--out", file});
    EXPECT_EQ(kept.exit_code, 2) << kept.err;
    EXPECT_NE(kept.err.find("the file exists (--force overwrites it)"), std::string::npos) << kept.err;
    EXPECT_EQ(test::read_text(file), "keep me\n");
    const auto forced = test::run_vibroimpact({"new", "bridge", "--out", file, "--force"});
    EXPECT_EQ(forced.exit_code, 0) << forced.err;
    EXPECT_NE(test::read_text(file), "keep me\n");
    const auto unknown = test::run_vibroimpact({"new", "membrane"});
    EXPECT_EQ(unknown.exit_code, 2);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vi
