#pragma once
// The cases of the paper's numerical study (examples/paper/), read from the built-in copies or from
// a folder that holds files of the same names.

#include <string>

#include "model/case.hpp"

namespace vi {

// The three cases the study starts from, each with the name it is reported under.
struct PaperCases {
    Case cantilever;          // cantilever.toml: modes (Figs. 2, 6, 7, 8); supports[0] is moved
    Case free_impact;         // free_impact_tip.toml: Fig. 3, and moved along the beam for Figs. 4, 5, 10, 11
    Case prestress;           // free_impact_prestress.toml: its prestress is scanned for Fig. 9
    std::string source;       // "built-in examples/paper/" or the folder read
};

// File names the study needs in examples/paper/ (or in the folder given).
inline constexpr const char* kCantileverFile = "cantilever.toml";
inline constexpr const char* kFreeImpactFile = "free_impact_tip.toml";
inline constexpr const char* kPrestressFile = "free_impact_prestress.toml";

// Reads the three cases from `folder`, or from the built-in copies when folder is empty. Throws
// InputError ("FILE:LINE: KEY: reason", built-in files named examples/paper/NAME) when a file is
// missing or bad, or when a case does not fit its part of the study (no support, no transient).
PaperCases load_paper_cases(const std::string& folder);

}  // namespace vi
