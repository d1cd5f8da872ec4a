#pragma once
// Value lists written on the command line: "0.5,0.67,0.78", "start:stop:count", "log:start:stop:count".

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "io/units.hpp"

namespace vi {

// Expands a spec into its values: a comma list, a linear range with count points (stop included;
// count 1 gives start), or a geometric range (start, stop > 0). Values are plain SI numbers, or, when
// `unit_of` is given, quantities with one of its units as in case files ("0.5um", "2 GPa"). Throws
// std::invalid_argument with a one-line reason for an empty spec, a non-numeric or non-finite value,
// a wrong unit, count < 1, or a bad log range.
std::vector<double> parse_range_spec(std::string_view spec, std::optional<Dimension> unit_of = std::nullopt);

// One value as parse_range_spec reads it: a plain SI number, or a quantity of dimension `unit_of`.
double parse_value(std::string_view text, std::optional<Dimension> unit_of = std::nullopt);

// The whole text as one finite number (strtod syntax), or nullopt.
std::optional<double> finite_number(std::string_view text);

// "LOW:HIGH" as two values (parse_value); nullopt when it is not exactly that. (LOW < HIGH is the caller's.)
std::optional<std::pair<double, double>> parse_bounds(std::string_view text, std::optional<Dimension> unit_of = std::nullopt);

}  // namespace vi
