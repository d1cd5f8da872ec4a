#include "study/analyses/sweep_analyses.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>

namespace vi {

std::vector<SweepCell> stiction_cells(const StictionResult& r, const Case& c) {
    bool stuck = false;
    std::optional<double> force_margin;
    double adhesion_margin = std::numeric_limits<double>::infinity();
    bool held_whatever = false;
    for (const SupportStiction& s : r.supports) {
        stuck = stuck || s.sticks;
        const double f = s.restoring_force - s.pull_off_force;
        force_margin = force_margin ? std::min(*force_margin, f) : f;
        if (s.critical_work_of_adhesion) {
            const double w = c.supports[static_cast<std::size_t>(s.support)].work_of_adhesion;
            adhesion_margin = std::min(adhesion_margin, *s.critical_work_of_adhesion - w);
        } else {
            held_whatever = true;
        }
    }
    for (const LayerStiction& l : r.layers) {
        stuck = stuck || l.hold.sticks;
        const Electrode& e = c.electrodes[l.hold.electrode];
        adhesion_margin = std::min(adhesion_margin, l.hold.critical_work_of_adhesion - e.work_of_adhesion.value_or(0.0));
    }
    std::optional<double> detached;
    if (!r.detached.empty()) {
        detached = r.detached.front().closed_form;
    } else {
        for (const LayerStiction& l : r.layers) {
            if (!detached && l.detached_closed_form) detached = l.detached_closed_form;
        }
    }
    const bool margin_defined = !held_whatever && adhesion_margin < std::numeric_limits<double>::infinity();
    // Pushed one by one: GCC 12 warns (-Wmaybe-uninitialized) on a braced list of variants holding strings.
    std::vector<SweepCell> cells;
    cells.emplace_back(static_cast<std::int64_t>(stuck ? 1 : 0));
    cells.push_back(force_margin ? SweepCell(*force_margin) : SweepCell());
    cells.push_back(margin_defined ? SweepCell(adhesion_margin) : SweepCell());
    cells.push_back(detached ? SweepCell(*detached) : SweepCell());
    return cells;
}

std::vector<SweepCell> air_q_cells(const AirQPoint& p) {
    std::vector<SweepCell> cells;
    for (double v : {p.pressure, p.knudsen, p.viscosity_ratio, p.squeeze_number, p.q_modal}) cells.emplace_back(v);
    cells.push_back(p.q_ringdown ? SweepCell(*p.q_ringdown) : SweepCell());
    return cells;
}

SweepSettings with_study_analyses(SweepSettings settings) {
    if (settings.analysis == SweepAnalysis::stiction) {
        settings.study_analysis = [](const Case& c) { return stiction_cells(stiction_check(c), c); };
    } else if (settings.analysis == SweepAnalysis::air_q) {
        settings.study_analysis = [](const Case& c) {
            // The film is the case's own (an electrode's or a [[films]] entry's): no made-up gap.
            const Case q = air_q_case(c, 0.0);
            return air_q_cells(air_q_point(q, q.air->pressure));
        };
    }
    return settings;
}

}  // namespace vi
