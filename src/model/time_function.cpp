#include "model/time_function.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vi {

double TimeFunction::operator()(double t) const {
    switch (kind) {
        case Kind::constant: return 1.0;
        case Kind::step: return t >= t_on ? 1.0 : 0.0;
        case Kind::harmonic: return offset + std::sin(2.0 * std::numbers::pi * frequency_hz * t + phase);
        case Kind::table: {
            if (times.empty()) return 0.0;
            if (t <= times.front()) return values.front();
            if (t >= times.back()) return values.back();
            const auto it = std::upper_bound(times.begin(), times.end(), t);
            const std::size_t i = static_cast<std::size_t>(it - times.begin());
            const double w = (t - times[i - 1]) / (times[i] - times[i - 1]);
            return values[i - 1] + w * (values[i] - values[i - 1]);
        }
    }
    return 0.0;
}

double TimeFunction::slope(double t) const {
    switch (kind) {
        case Kind::constant:
        case Kind::step: return 0.0;
        case Kind::harmonic: {
            const double w = 2.0 * std::numbers::pi * frequency_hz;
            return w * std::cos(w * t + phase);
        }
        case Kind::table: {
            if (times.size() < 2 || t < times.front() || t >= times.back()) return 0.0;
            const auto it = std::upper_bound(times.begin(), times.end(), t);
            const std::size_t i = static_cast<std::size_t>(it - times.begin());
            return (values[i] - values[i - 1]) / (times[i] - times[i - 1]);
        }
    }
    return 0.0;
}

double TimeFunction::max_abs() const {
    switch (kind) {
        case Kind::constant:
        case Kind::step: return 1.0;
        case Kind::harmonic: return std::abs(offset) + 1.0;
        case Kind::table: {
            double m = 0.0;
            for (double v : values) m = std::max(m, std::abs(v));
            return m;
        }
    }
    return 0.0;
}

std::vector<double> TimeFunction::breakpoints(double t0, double t1) const {
    std::vector<double> out;
    if (kind == Kind::step && t_on > t0 && t_on < t1) out.push_back(t_on);
    if (kind == Kind::table) {
        for (double k : times) {
            if (k > t0 && k < t1) out.push_back(k);
        }
    }
    return out;
}

}  // namespace vi
