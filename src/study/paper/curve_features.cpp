#include "study/paper/curve_features.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vi {
namespace {

// Highest value from i outwards in direction step until the curve falls below y[i], ends or has a gap.
double rise(const std::vector<std::optional<double>>& y, std::size_t i, int step) {
    double top = *y[i];
    for (long j = static_cast<long>(i) + step; j >= 0 && j < static_cast<long>(y.size()); j += step) {
        const auto& v = y[static_cast<std::size_t>(j)];
        if (!v || *v < *y[i]) break;
        top = std::max(top, *v);
    }
    return top - *y[i];
}

}  // namespace

std::vector<CurveMinimum> local_minima(const std::vector<double>& x, const std::vector<std::optional<double>>& y) {
    if (x.size() != y.size()) throw std::invalid_argument("local_minima: x and y differ in length");
    std::vector<CurveMinimum> out;
    const std::size_t n = y.size();
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (!y[i] || !y[i - 1] || *y[i - 1] <= *y[i]) continue;
        // Walk over a flat bottom; it is a minimum if the curve then rises.
        std::size_t k = i;
        while (k + 1 < n && y[k + 1] && *y[k + 1] == *y[i]) ++k;
        if (k + 1 >= n || !y[k + 1] || *y[k + 1] < *y[i]) continue;
        CurveMinimum m;
        m.index = i;
        m.x = x[i];
        m.y = *y[i];
        if (k == i) {
            // Vertex of the parabola through the three samples (uneven spacing allowed).
            const double x0 = x[i - 1], x1 = x[i], x2 = x[i + 1];
            const double y0 = *y[i - 1], y1 = *y[i], y2 = *y[i + 1];
            const double d01 = (y1 - y0) / (x1 - x0), d12 = (y2 - y1) / (x2 - x1);
            const double a = (d12 - d01) / (x2 - x0);
            if (a > 0.0) {
                const double b = d01 - a * (x0 + x1);
                const double xv = -b / (2.0 * a);
                if (xv > x0 && xv < x2) {
                    m.x = xv;
                    m.y = y1 + (xv - x1) * (d01 + a * (xv - x0));
                }
            }
        }
        m.prominence = std::min(rise(y, i, -1), rise(y, k, +1));
        out.push_back(m);
        i = k;
    }
    return out;
}

std::optional<CurveMinimum> nearest_minimum(const std::vector<CurveMinimum>& minima, double x0) {
    std::optional<CurveMinimum> best;
    for (const CurveMinimum& m : minima) {
        if (!best || std::abs(m.x - x0) < std::abs(best->x - x0)) best = m;
    }
    return best;
}

std::optional<std::size_t> smallest_sample(const std::vector<std::optional<double>>& y) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (y[i] && (!best || *y[i] < *y[*best])) best = i;
    }
    return best;
}

}  // namespace vi
