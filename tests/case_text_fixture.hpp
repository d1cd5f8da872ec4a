#pragma once
// The small valid case text the case-reader tests edit line by line (line numbers stay known).

#include <string>

namespace vi::test {

// A valid clamped-free case, one key per line, 10 lines; tables appended start at line 11.
inline const std::string kBaseCase =
    "name = \"t\"\n"                  // 1
    "[beam]\n"                        // 2
    "length = \"100 um\"\n"           // 3
    "width = \"30 um\"\n"             // 4
    "thickness = \"2 um\"\n"          // 5
    "elements = 20\n"                 // 6
    "[material]\n"                    // 7
    "youngs_modulus = \"200 GPa\"\n"  // 8
    "density = \"8900 kg/m^3\"\n"     // 9
    "poisson_ratio = 0.3\n";          // 10

}  // namespace vi::test
