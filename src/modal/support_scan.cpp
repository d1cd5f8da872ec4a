#include "modal/support_scan.hpp"

#include <stdexcept>

#include "model/run_control.hpp"

namespace vi {

std::vector<SupportScanPoint> support_scan(const Case& c, const std::vector<double>& positions, int count,
                                           SupportModel model) {
    if (c.supports.empty()) throw std::invalid_argument("support scan: the case has no support to move");
    std::vector<SupportScanPoint> out;
    out.reserve(positions.size());
    for (double p : positions) {
        check_run();
        Case moved = c;
        moved.supports[0].position = p;
        out.push_back({p, modal_study(moved, count, model)});
    }
    return out;
}

}  // namespace vi
