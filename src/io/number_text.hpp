#pragma once
// Numbers as the shortest text that reads back to the same double (for byte-stable CSV files).

#include <string>

namespace vi {

// The shortest decimal text that parses back to exactly v ("0.9", "5.2637869086937046e-06"); the
// same bits give the same text on every machine. "nan", "inf" and "-inf" for non-finite values.
std::string round_trip_text(double v);

}  // namespace vi
