#pragma once
// Checks that a case's numbers leave a problem double precision can compute: every value and derived
// scale of a sane magnitude, contacts not too stiff for the beam (docs/case-files.md, "Limits").

#include <vector>

#include "model/case.hpp"
#include "model/case_checks.hpp"

namespace vi {

// Appends the magnitude problems of c's derived scales to out: a derived scale of the beam (A, I, EI,
// rho A, its mass, EI/l^3, omega_1^2, the mesh's highest omega^2) outside [1/kMagnitudeLimit,
// kMagnitudeLimit]; a support stiffer than kMaxContactRatio EI/l^3, or whose damper at omega_1 is.
// The values themselves are check_key_values's (model/key_checks.hpp).
void check_magnitudes(std::vector<CaseProblem>& out, const Case& c);

}  // namespace vi
