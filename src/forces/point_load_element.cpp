#include "forces/point_load_element.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

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

namespace {

class PointLoads final : public ElementFamily {
public:
    [[nodiscard]] std::string_view name() const override { return "point loads"; }

    [[nodiscard]] std::vector<FamilyElement> elements(const ElementSource& src) const override {
        std::vector<FamilyElement> out;
        for (std::size_t k = 0; k < src.c.loads.size(); ++k) {
            const PointLoad& load = src.c.loads[k];
            const Eigen::VectorXd shape = unit_point_load(src.system, load.position);
            std::vector<int> dofs;
            std::vector<double> weights;
            for (Eigen::Index i = 0; i < shape.size(); ++i) {
                if (shape[i] == 0.0) continue;
                dofs.push_back(static_cast<int>(i));
                weights.push_back(shape[i]);
            }
            out.push_back({std::make_shared<PointLoadElement>("loads[" + std::to_string(k) + "]", std::move(dofs),
                                                              std::move(weights), load.amplitude, load.time,
                                                              load.position * src.system.length),
                           {"loads", k}});
        }
        return out;
    }
};

}  // namespace

const ElementFamily& point_loads() {
    static const PointLoads family;
    return family;
}

}  // namespace vi
