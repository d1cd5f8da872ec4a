#include "impacts/electrical_ledger.hpp"

#include <cmath>

namespace vi {

std::optional<ElectricalLedger> electrical_ledger(const ContactConduction& c) {
    if (std::isnan(c.r_on)) return std::nullopt;
    ElectricalLedger l;
    l.contact = c.contact;
    l.r_on = c.r_on;
    const std::vector<ConductionStretch>& s = c.stretches;
    if (!s.empty()) l.first_closure = s.front().t_on;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i].on_at_end) {
            l.settle_time = s[i].t_on;
            break;
        }
        ElectricalOpening o{s[i].t_off, std::nullopt, s[i].min_resistance};
        if (i + 1 < s.size()) o.duration = s[i + 1].t_on - s[i].t_off;
        l.openings.push_back(o);
    }
    l.bounces = static_cast<int>(l.openings.size());
    return l;
}

}  // namespace vi
