#pragma once
// Supported-beam modes as one support moves along the beam (the paper's Figs. 6-8).

#include <vector>

#include "modal/modal_analysis.hpp"
#include "model/case.hpp"

namespace vi {

// Modal study at one support position x0/l.
struct SupportScanPoint {
    double position = 0.0;   // x0 / l
    ModalStudy study;
};

// Moves supports[0] of the case to each position (the other supports stay) and runs modal_study.
// Throws std::invalid_argument when the case has no support.
std::vector<SupportScanPoint> support_scan(const Case& c, const std::vector<double>& positions, int count,
                                           SupportModel model);

}  // namespace vi
