#include "model/case.hpp"

namespace vi {

double Material::effective_modulus() const {
    return plate_modulus ? youngs_modulus / (1.0 - poisson_ratio * poisson_ratio) : youngs_modulus;
}

}  // namespace vi

namespace vi {

double Air::lambda() const {
    if (mean_free_path) return *mean_free_path;
    return kMeanFreePath0 * (kAirPressure0 / pressure) * (temperature / kAirTemperature0);
}

}  // namespace vi
