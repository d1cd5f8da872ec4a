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

std::vector<double> time_stops(const ForceSet& forces, double t0, double t1) {
    std::vector<double> out;
    for (const ForceElementPtr& e : forces) {
        for (double b : e->time_stops(t0, t1)) out.push_back(b);
    }
    std::sort(out.begin(), out.end());
    const auto same = [](double a, double b) {
        return std::abs(a - b) <= 8.0 * std::numeric_limits<double>::epsilon() * std::max({std::abs(a), std::abs(b), 1e-300});
    };
    out.erase(std::unique(out.begin(), out.end(), same), out.end());
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
