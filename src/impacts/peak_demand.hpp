#pragma once
// The peaks a caller of the impact summary reads: those of the first impacts in full, of any later
// episode only whether it passes the settle threshold that decides T_p (TransientOptions::peak_level).

#include <functional>
#include <vector>

#include "dynamics/transient_result.hpp"
#include "impacts/impact_summary.hpp"

namespace vi {

// TransientOptions::peak_level for a caller that reads the peaks of the first `leading` impacts
// (grouped as summarize_impacts groups them) and of no other: their episodes get the level -inf
// (peaks in full); a later episode the settle threshold as known so far, settle_tolerance times the
// first impact's peak penetration [m] (the first impact's peak can only grow, so the level never
// exceeds the final threshold and T_p is decided as from full peaks), or +inf when T_p is settled by
// approach speed. The function keeps the grouping of the episodes it has seen; it must be called
// once per episode in onset order (a vector of any other length makes it start over).
std::function<double(const std::vector<ContactEpisode>&)> leading_impacts_peak_level(const ImpactSettings& s, int leading);

}  // namespace vi
