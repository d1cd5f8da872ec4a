#pragma once
// CaseProblem: one thing wrong with a case, tied to the key that caused it.

#include <string>

namespace vi {

// The dotted key path (e.g. "supports[1].position") and what is wrong, in one line.
struct CaseProblem {
    std::string key;
    std::string message;
};

}  // namespace vi
