#include "model/golden_section.hpp"

#include <cmath>

namespace vi {

GoldenSectionPeak golden_section_max(const std::function<double(double)>& f, double a, double b, double width) {
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = f(x1), f2 = f(x2);
    // Each pass narrows the bracket by g: after 2000 (g^2000 ~ 1e-418) any bracket of doubles is at
    // the roundoff of x, where a smaller width cannot be had.
    for (int pass = 0; pass < 2000 && b - a > width; ++pass) {
        if (f1 > f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
    }
    const double x = 0.5 * (a + b);
    return {x, f(x)};
}

}  // namespace vi
