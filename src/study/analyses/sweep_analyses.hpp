#pragma once
// The sweep analyses whose code lives in the studies (the stiction check, Q in air): their cells in
// the order of sweep_result_columns, and sweep settings that carry them.

#include <vector>

#include "model/case.hpp"
#include "study/air/air_q.hpp"
#include "study/stiction/stiction.hpp"
#include "sweep/columns.hpp"
#include "sweep/runner.hpp"

namespace vi {

// `settings` with study_analysis set for a stiction or air-q analysis (unchanged for the others).
SweepSettings with_study_analyses(SweepSettings settings);

// stuck (1 when some adhesive support or adhesive layer holds the unloaded beam), force_margin_n
// (the smallest restoring force less pull-off force over the adhesive supports, > 0 releasing),
// adhesion_margin_j_m2 (the smallest critical work of adhesion less the contact's own over supports
// and layers; empty when a support is pressed on unloaded: it holds whatever the adhesion),
// detached_length_m (the first S-shaped stuck cantilever's closed-form detached length). `c` is the
// case the check ran on.
std::vector<SweepCell> stiction_cells(const StictionResult& r, const Case& c);

// pressure_pa, knudsen, viscosity_ratio, squeeze_number, q_modal, q_ringdown (empty when the
// ring-down has too few maxima: overdamped).
std::vector<SweepCell> air_q_cells(const AirQPoint& p);

}  // namespace vi
