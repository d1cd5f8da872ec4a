#include "model/bisection.hpp"

namespace vi {

double bisect_sign_change(const std::function<double(double)>& f, double a, double b) {
    double fa = f(a);
    for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (a + b);
        if (mid <= a || mid >= b) break;
        const double fm = f(mid);
        if (fm == 0.0) return mid;
        if ((fm < 0) == (fa < 0)) {
            a = mid;
            fa = fm;
        } else {
            b = mid;
        }
    }
    return 0.5 * (a + b);
}

}  // namespace vi
