#include "forces/point_load_element.hpp"

#include <cmath>
#include <stdexcept>

namespace vi {

PointLoadElement::PointLoadElement(std::string name, std::vector<int> dofs, std::vector<double> weights, double amplitude,
                     TimeFunction g, double x)
    : name_(std::move(name)), dofs_(std::move(dofs)), weights_(std::move(weights)), amplitude_(amplitude),
      g_(std::move(g)), x_(x) {
    if (dofs_.size() != weights_.size() || !std::isfinite(amplitude_)) {
        throw std::invalid_argument(name_ + ": inconsistent point load data");
    }
}

void PointLoadElement::add_force(const ElementState& s, int, double* f) const {
    const double q = amplitude_ * g_(s.t);
    for (std::size_t i = 0; i < weights_.size(); ++i) f[i] += q * weights_[i];
}

double PointLoadElement::input_power(const ElementState& s, int) const {
    double v = 0.0;
    for (std::size_t i = 0; i < weights_.size(); ++i) v += weights_[i] * s.v[i];
    return amplitude_ * g_(s.t) * v;
}

std::optional<LinearForm> PointLoadElement::linear_form() const {
    return LinearForm{TimeForcing{dofs_, weights_, amplitude_, g_}};
}

}  // namespace vi
