#include "model/case.hpp"

#include <numbers>

namespace vi {

double Material::effective_modulus() const {
    return plate_modulus ? youngs_modulus / (1.0 - poisson_ratio * poisson_ratio) : youngs_modulus;
}

// Derjaguin, Muller & Toporov (1975) and Johnson, Kendall & Roberts (1971); Maugis (2000) ch. 3-4.
double Support::pull_off_force() const {
    const double pi_rw = std::numbers::pi * contact_radius * work_of_adhesion;
    switch (adhesion) {
        case Adhesion::none: return 0.0;
        case Adhesion::dmt: return 2.0 * pi_rw;
        case Adhesion::jkr: return 1.5 * pi_rw;
    }
    return 0.0;
}

}  // namespace vi

namespace vi {

double Air::lambda() const {
    if (mean_free_path) return *mean_free_path;
    return kMeanFreePath0 * (kAirPressure0 / pressure) * (temperature / kAirTemperature0);
}

}  // namespace vi
