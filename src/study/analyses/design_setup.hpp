#pragma once
// A design problem from what `vibroimpact optimize` is given (docs/optimization.md): each design
// computed as a sweep point of any analysis, the study ones (stiction, air-q) included.

#include <string>
#include <vector>

#include "design/design_problem.hpp"
#include "model/case.hpp"

namespace vi {

struct DesignRequest {
    std::vector<std::string> vary;         // --vary settings "PATH=LOW:HIGH"
    std::string minimize, maximize;        // one of them: a reported quantity's name
    std::vector<std::string> constraints;  // "NAME<=VALUE" or "NAME>=VALUE"
    std::string analysis = "simulate";     // as sweep --analysis
    int modes = 3;                         // bending modes of a modes analysis
    double point_timeout = 60.0;           // wall-clock limit of one design [s] (0: none)
};

// The problem on the case `base`. Throws InputError naming the option: an analysis the case cannot
// run, a variable varied twice, neither or both of minimize and maximize, an unknown quantity.
DesignProblem design_problem(const Case& base, const DesignRequest& request);

}  // namespace vi
