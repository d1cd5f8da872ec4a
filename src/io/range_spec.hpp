#pragma once
// Value lists written on the command line: "0.5,0.67,0.78", "start:stop:count", "log:start:stop:count".

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace vi {

// Expands a spec into its values: a comma list, a linear range with count points (stop included;
// count 1 gives start), or a geometric range (start, stop > 0). Throws std::invalid_argument with a
// one-line reason for an empty spec, a non-numeric or non-finite value, count < 1, or a bad log range.
std::vector<double> parse_range_spec(std::string_view spec);

// The whole text as one finite number (strtod syntax), or nullopt.
std::optional<double> finite_number(std::string_view text);

// "LOW:HIGH" as two finite numbers; nullopt when it is not exactly that. (LOW < HIGH is the caller's.)
std::optional<std::pair<double, double>> parse_bounds(std::string_view text);

}  // namespace vi
