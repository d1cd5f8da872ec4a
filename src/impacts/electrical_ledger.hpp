#pragma once
// The bounce ledger of a contact as an oscilloscope on its circuit sees it: the contact is on while
// its resistance is below the threshold r_on, and every rise to r_on after the first closure is an
// electrical bounce (docs/hertz-contact.md §7).

#include <optional>
#include <string>
#include <vector>

#include "dynamics/transient_result.hpp"

namespace vi {

// One opening after the first closure.
struct ElectricalOpening {
    double t = 0.0;                      // the resistance rose to r_on, or the contact opened [s]
    std::optional<double> duration;      // until it fell below r_on again [s]; empty when open to the end
    double closure_min_resistance = 0.0; // smallest resistance of the closure before it [ohm]
};

struct ElectricalLedger {
    int contact = 0;                         // index among the contacts
    double r_on = 0.0;                       // the threshold [ohm]
    std::optional<double> first_closure;     // the resistance first below r_on [s]
    std::vector<ElectricalOpening> openings;
    int bounces = 0;                         // openings.size(): every opening, a final one included
    // Time from the start until the resistance stays below r_on to the end of the run [s]; empty when
    // it is not below r_on at the end.
    std::optional<double> settle_time;
};

// The ledger of c; nullopt when c has no threshold (r_on NaN).
std::optional<ElectricalLedger> electrical_ledger(const ContactConduction& c);

}  // namespace vi
