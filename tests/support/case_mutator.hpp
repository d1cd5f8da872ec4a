#pragma once
// Mutates case-file text for the fuzz test: values to extremes, units swapped, keys removed,
// duplicated or misspelled, wrong types, truncation, random bytes, extra tables.

#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace vi::test {

// One mutant: its text and what was done to the original, for messages.
struct Mutant {
    std::string text;
    std::vector<std::string> steps;  // one line per mutation, e.g. "value of line 12 -> 1e308"
    std::vector<std::pair<std::string, std::string>> files;  // files beside the case: name, text
};

// Deterministic: the same seed and index always give the same mutant of the same text.
Mutant mutate_case(const std::string& text, std::uint64_t seed, std::uint64_t index);

}  // namespace vi::test
