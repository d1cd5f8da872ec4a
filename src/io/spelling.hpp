#pragma once
// "Did you mean ...?" for misspelled names: the accepted name nearest to what was written.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vi {

// Edits (insert, delete, substitute, swap two neighbours) that turn a into b, case-sensitive.
int spelling_distance(std::string_view a, std::string_view b);

// The candidate nearest to word when it is a plausible misspelling (at most 2 edits, and fewer than
// half the longer name's length); the first of equally near ones; nullopt when none is that near.
std::optional<std::string> closest_spelling(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace vi
