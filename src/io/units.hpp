#pragma once
// Quantities written with a unit ("117 um", "207 GPa") converted to SI, with a strict list of units.

#include <string>
#include <string_view>

#include "model/dimension.hpp"

namespace vi {

// Human-readable list of the units accepted for a dimension, e.g. "m, mm, um, nm".
std::string accepted_units(Dimension d);

// Parses "<number> <unit>" (space optional) into SI; throws std::invalid_argument with a one-line
// reason when the number or unit is malformed, the unit is not one of d's, or the value is not finite.
double parse_quantity(std::string_view text, Dimension d);

// Name of a dimension for messages, with its article: "a length", "a pressure", "dimensionless".
std::string_view dimension_name(Dimension d);

// text in double quotes, with quotes, backslashes and control characters escaped, so that a message
// quoting user input stays on one line.
std::string in_quotes(std::string_view text);

}  // namespace vi
