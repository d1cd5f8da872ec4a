// The test helpers' own text checks: each accepts what it should and refuses the near misses.

#include <gtest/gtest.h>

#include "support/text_checks.hpp"

namespace vi::test {
namespace {

TEST(TextChecks, OneErrorLine) {
    EXPECT_TRUE(is_one_error_line("vibroimpact: error: a.toml:3: beam.length: must be positive\n"));
    EXPECT_FALSE(is_one_error_line("vibroimpact: error: \n"));
    EXPECT_FALSE(is_one_error_line("vibroimpact: error: two\nlines\n"));
    EXPECT_FALSE(is_one_error_line("vibroimpact: error: no newline"));
    EXPECT_FALSE(is_one_error_line("vibroimpact: failure: x\n"));
    EXPECT_FALSE(is_one_error_line(""));
}

TEST(TextChecks, AssignsKey) {
    EXPECT_TRUE(assigns_key("[solver]\nhorizon = \"1 us\"\n", "horizon"));
    EXPECT_TRUE(assigns_key("  horizon=1e-6", "horizon"));
    EXPECT_FALSE(assigns_key("# horizon = 1\n", "horizon"));
    EXPECT_FALSE(assigns_key("horizons = 1\n", "horizon"));
    EXPECT_FALSE(assigns_key("x = \"horizon = 1\"\n", "horizon"));
}

TEST(TextChecks, WholeWordsIgnoringCase) {
    EXPECT_EQ(find_word_ignoring_case("value -NaN here", {"nan", "inf"}), "NaN");
    EXPECT_EQ(find_word_ignoring_case("x = inf", {"nan", "inf"}), "inf");
    EXPECT_EQ(find_word_ignoring_case("dominant infinite info_nan", {"nan", "inf"}), "");
}

}  // namespace
}  // namespace vi::test
