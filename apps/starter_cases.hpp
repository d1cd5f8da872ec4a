#pragma once
// The starter cases `vibroimpact new` writes: the tested example cases, embedded at build time.

#include <string_view>
#include <vector>

namespace vi::cli {

struct StarterCase {
    std::string_view kind;     // "cantilever", "bridge", ...
    std::string_view example;  // the example file it is, relative to the source tree
    std::string_view text;     // the case file
};

// Every kind, in the order `new --help` lists them.
const std::vector<StarterCase>& starter_cases();

}  // namespace vi::cli
