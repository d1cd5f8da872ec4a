#pragma once
// Numbers as text for messages and reports (not for data files: those use round_trip_text).

#include <string>

namespace vi {

// v with `digits` significant digits, printf's "%.*g" ("0.0012", "1.5e+03").
std::string significant(double v, int digits);
// v with `places` digits after the point, printf's "%.*f" ("12.35").
std::string decimals(double v, int places);
// v through a printf format with one double conversion ("%.4g V"); the text is cut at 127 bytes.
std::string formatted(const char* format, double v);

}  // namespace vi
