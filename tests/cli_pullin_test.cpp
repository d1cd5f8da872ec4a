// `vibroimpact pullin` from the command line: what it says when it has no answer to give.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

// The switch example with its stop 0.5 um under the tip: the tip lands on it (touch-down) before
// the open branch folds (pull-in would move the tip 1.03 um), so there is no static pull-in for
// --dynamic to bracket. That is a failure with the usual one line, and nothing is written.
TEST(PullinCommand, DynamicWithoutAStaticPullinFailsWithOneLineAndWritesNothing) {
    std::string text = test::read_text(test::source_path("examples/switch/cantilever_switch.toml"));
    const std::string stop = "gap = \"1.5 um\"";
    ASSERT_NE(text.find(stop), std::string::npos);
    text.replace(text.find(stop), stop.size(), "gap = \"0.5 um\"");
    const std::string dir = test::make_temp_dir();
    test::write_text(dir + "/case.toml", text);

    const auto plain = test::run_vibroimpact({"pullin", dir + "/case.toml", "--json"});
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_NE(plain.out.find("\"touchdown\""), std::string::npos);

    const auto r = test::run_vibroimpact({"pullin", dir + "/case.toml", "--dynamic", "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err,
              "vibroimpact: failure: pullin --dynamic: needs a static pull-in to bracket, and the branch has none "
              "(a support closes first)\n");
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out"));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vi
