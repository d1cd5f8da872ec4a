// The transverse force a beam model's force element named `name` puts on the beam at rest (every
// displacement and speed zero) at time t, summed over its deflection DOFs [N]; NaN when no element
// has that name.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "problem/beam_model.hpp"

namespace vi::test {

inline double rest_force(const BeamModel& b, const std::string& name, double t) {
    for (const auto& element : b.forces) {
        if (element->name() != name) continue;
        const std::vector<double> zero(element->dofs().size(), 0.0);
        std::vector<double> f(element->dofs().size(), 0.0);
        element->add_force(ElementState{t, zero.data(), zero.data(), zero.data()}, 0, f.data());
        double total = 0.0;
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (b.is_v[static_cast<std::size_t>(element->dofs()[i])]) total += f[i];
        }
        return total;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace vi::test
