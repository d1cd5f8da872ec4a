#include "forces/force_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vi {

const ForceElement* first_nonlinear(const ForceSet& forces) {
    for (const ForceElementPtr& e : forces) {
        if (!e->linear_form()) return e.get();
    }
    return nullptr;
}

std::vector<TimeBreak> time_stops(const ForceSet& forces, double t0, double t1) {
    std::vector<TimeBreak> all;
    for (const ForceElementPtr& e : forces) {
        for (const TimeBreak& b : e->time_stops(t0, t1)) all.push_back(b);
    }
    std::sort(all.begin(), all.end(), [](const TimeBreak& a, const TimeBreak& b) { return a.t < b.t; });
    const auto same = [](double a, double b) {
        return std::abs(a - b) <= 8.0 * std::numeric_limits<double>::epsilon() * std::max({std::abs(a), std::abs(b), 1e-300});
    };
    std::vector<TimeBreak> out;
    for (const TimeBreak& b : all) {
        if (!out.empty() && same(out.back().t, b.t)) {
            out.back().jump = out.back().jump || b.jump;
        } else {
            out.push_back(b);
        }
    }
    return out;
}

std::vector<int> contact_indices(const ForceSet& forces) {
    std::vector<int> out;
    for (std::size_t i = 0; i < forces.size(); ++i) {
        if (forces[i]->is_contact()) out.push_back(static_cast<int>(i));
    }
    return out;
}

}  // namespace vi
