// "Did you mean ...?": the distance between names and the choice of the nearest accepted one.

#include <gtest/gtest.h>

#include "io/spelling.hpp"

namespace {

TEST(Spelling, DistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(vi::spelling_distance("stiffness", "stiffness"), 0);
    EXPECT_EQ(vi::spelling_distance("stifness", "stiffness"), 1);  // one letter left out
    EXPECT_EQ(vi::spelling_distance("lenght", "length"), 1);       // two neighbours swapped
    EXPECT_EQ(vi::spelling_distance("gab", "gap"), 1);
    EXPECT_EQ(vi::spelling_distance("", "gap"), 3);
    EXPECT_EQ(vi::spelling_distance("kitten", "sitting"), 3);      // Levenshtein's classic example
}

TEST(Spelling, ClosestIsAPlausibleMisspellingOrNothing) {
    const std::vector<std::string_view> keys{"position", "gap", "prestress", "stiffness", "damping"};
    EXPECT_EQ(vi::closest_spelling("stifness", keys), "stiffness");
    EXPECT_EQ(vi::closest_spelling("dampnig", keys), "damping");
    EXPECT_EQ(vi::closest_spelling("positon", keys), "position");
    EXPECT_FALSE(vi::closest_spelling("colour", keys));  // nothing near
    EXPECT_FALSE(vi::closest_spelling("ga", {"gap", "go"}) == std::nullopt);
    EXPECT_FALSE(vi::closest_spelling("xy", {"gap"}));    // 3 edits in a 3-letter name is not a misspelling
    EXPECT_FALSE(vi::closest_spelling("stiffness", {}));
}

}  // namespace
