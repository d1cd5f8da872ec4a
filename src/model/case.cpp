#include "model/case.hpp"

namespace vi {

double Material::effective_modulus() const {
    return plate_modulus ? youngs_modulus / (1.0 - poisson_ratio * poisson_ratio) : youngs_modulus;
}

}  // namespace vi
