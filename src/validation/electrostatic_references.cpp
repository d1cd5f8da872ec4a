#include "validation/electrostatic_references.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "model/golden_section.hpp"

namespace vi {

std::shared_ptr<const ElectrostaticPad> parallel_plate_pad(double gap, double width, double length, double voltage,
                                                          TimeFunction time) {
    PadPoint p;
    p.x = 0.5 * length;
    p.weight = length;
    p.local = {0, -1, -1, -1};
    p.shape = {1.0, 0.0, 0.0, 0.0};
    PadGeometry geo;
    geo.gap = gap;
    geo.width = width;
    geo.to = length;
    return std::make_shared<const ElectrostaticPad>("electrodes[0]", std::vector<int>{0}, std::vector<PadPoint>{p}, geo,
                                                    voltage, std::move(time));
}

PullinModel parallel_plate_model(double k, double mass, double gap, double width, double length) {
    PullinModel m;
    m.K.resize(1, 1);
    m.K.insert(0, 0) = k;
    m.M.resize(1, 1);
    m.M.insert(0, 0) = mass;
    m.pads = {parallel_plate_pad(gap, width, length, 1.0, TimeFunction{})};
    m.row = Eigen::VectorXd::Constant(1, -1.0);  // travel toward the electrode below = -v
    m.air_gap = gap;
    return m;
}

double cantilever_pullin_lambda_shooting() {
    const auto residual = [](const Eigen::Vector3d& x, double tip) {
        const int n = 4000;
        const double h = 1.0 / n;
        Eigen::Vector4d y(0, 0, x[0], x[1]);
        const auto rhs = [&](const Eigen::Vector4d& s) {
            return Eigen::Vector4d(s[1], s[2], s[3], x[2] / ((1 - s[0]) * (1 - s[0])));
        };
        for (int i = 0; i < n; ++i) {
            const Eigen::Vector4d k1 = rhs(y), k2 = rhs(y + 0.5 * h * k1), k3 = rhs(y + 0.5 * h * k2), k4 = rhs(y + h * k3);
            y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        }
        return Eigen::Vector3d(y[2], y[3], y[0] - tip);
    };
    Eigen::Vector3d x(0, 0, 0);
    // lambda at a prescribed tip deflection, by Newton from the last solution.
    const auto lambda_at = [&](double tip) {
        for (int it = 0; it < 30; ++it) {
            const Eigen::Vector3d r = residual(x, tip);
            Eigen::Matrix3d j;
            for (int c = 0; c < 3; ++c) {
                Eigen::Vector3d d = x;
                d[c] += 1e-7 * (1 + std::abs(x[c]));
                j.col(c) = (residual(d, tip) - r) / (d[c] - x[c]);
            }
            const Eigen::Vector3d dx = j.fullPivLu().solve(-r);
            x += dx;
            if (dx.norm() < 1e-13 * (1 + x.norm())) break;
        }
        return x[2];
    };
    double best_tip = 0.0, best = 0.0;
    for (int step = 1; step <= 60; ++step) {
        const double l = lambda_at(0.01 * step);
        if (l > best) {
            best = l;
            best_tip = 0.01 * step;
        }
    }
    // The largest lambda around the best grid point.
    return golden_section_max(lambda_at, best_tip - 0.01, best_tip + 0.01, 1e-10).value;
}

}  // namespace vi
