#pragma once
// Impact characteristics of a transient (docs/model.md §14): episodes grouped into impacts, the
// periods T, T1, T2, the transient duration T_p, rebound y_max and their dimensionless forms.

#include <optional>
#include <string>
#include <vector>

#include "dynamics/transient_result.hpp"

namespace vi {

// One impact in the paper's sense: episodes of one support separated by flights shorter than
// group_gap (or each episode alone, without grouping). Onset and pre-impact velocity of the first episode, end of the last, largest peaks,
// summed impulse and contact energy.
struct Impact {
    int support = 0;
    double t_on = 0.0, t_off = 0.0;   // [s]
    double v_in = 0.0, v_out = 0.0;   // contact point velocity at onset / final separation [m/s]
    double peak_force = 0.0;          // [N]
    double peak_penetration = 0.0;    // [m]
    double impulse = 0.0;             // [N s]
    int episodes = 0;
    bool closed_at_end = false;
    double contact_energy = 0.0;      // summed over its episodes [J]; NaN where not recorded
    double peak_pressure = 0.0;       // largest Hertz p0 [Pa]; NaN for a law without one
    std::optional<bool> yielded;      // some episode passed the yield onset; empty without Y
};

// The damage indicators of a run (or of one actuation cycle) summed over its impacts.
struct ContactDamage {
    double contact_energy = 0.0;     // [J]; NaN where some episode's is not recorded
    double peak_force = 0.0;         // [N]
    double peak_pressure = 0.0;      // largest over the impacts that have one [Pa]; NaN when none has
    int yield_impacts = 0;           // impacts whose p0 passed 1.6 Y
    bool yield_known = false;        // some impact had a yield strength to check against
};
ContactDamage contact_damage(const std::vector<Impact>& impacts);

// What the summary needs besides the solver's result.
struct ImpactSettings {
    double omega1 = 0.0;             // first circular frequency of the unsupported beam [rad/s]
    double group_gap = 0.0;          // [s]; 0 = a quarter of 2 pi / omega1
    double settle_tolerance = 0.01;  // fraction of the first impact's peak penetration
    bool group = true;               // false: every contact episode is an impact (no grouping)
    bool settle_by_velocity = false; // T_p by approach speed |v_in| >= settle_velocity instead
    double settle_velocity = 0.0;    // [m/s]
    double length = 0.0;             // l [m], for z_max
    double tip_equilibrium = 0.0;    // final static v of the watched point [m]
    double contact_equilibrium = 0.0;  // final static v at support 0 [m]
};

struct ImpactSummary {
    double group_gap = 0.0;
    std::vector<Impact> impacts;        // in onset order, all supports
    int cycle_support = 0;              // support whose impacts define T, T1, T2
    std::vector<double> T, T1, T2;      // per cycle [s]
    std::optional<double> T_first, T1_first, T2_first;
    std::optional<double> Tp;           // [s]; empty when the horizon ended first or nothing hit
    std::string Tp_reason;              // "settled", "persistent_contact", "horizon", "no_impact", "at_rest",
                                        // "below_threshold" (velocity rule: no impact as fast as settle_velocity),
                                        // "collapsed" (the beam reached an electrode, which ended the run)
    std::optional<double> y_max, z_max, y_max_contact, watched_min;  // [m], [-], [m], [m]
};

// The longest flight between two contact episodes of one support that still groups them into one
// impact [s]: s.group_gap, a quarter period of mode 1 when that is 0, or 0 without grouping.
double grouping_gap(const ImpactSettings& s);

// Episodes whose peaks were not computed (NaN: TransientOptions::peak_level) add nothing to their
// impact's peaks, so such an impact is never above the settle threshold.
ImpactSummary summarize_impacts(const TransientResult& r, const ImpactSettings& s);

}  // namespace vi
