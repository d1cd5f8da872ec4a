#pragma once
// A load's time function g(t) from a two-column CSV table (header "t_s,g").

#include <string>

#include "model/time_function.hpp"

namespace vi {

// Parses CSV text into g (kind table): the header row "t_s,g", then one "time,value" row per line
// (plain numbers, SI seconds), times strictly increasing; blank lines are skipped. Throws
// InputError("FILE:LINE: reason") at the first bad line.
void parse_load_table(const std::string& text, const std::string& file, TimeFunction& g);

// The same for a table whose second column is named `column` ("V_V" for a voltage in volts).
void parse_time_table(const std::string& text, const std::string& file, const std::string& column, TimeFunction& g);

}  // namespace vi
