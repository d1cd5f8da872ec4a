#include "sweep/grid.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>

#include "model/input_error.hpp"
#include "io/number_text.hpp"
#include "io/range_spec.hpp"

namespace vi {

SweepAxis parse_sweep_setting(const std::string& setting, const Case& c) {
    const auto fail = [&](const std::string& reason) { return InputError("--set", setting, reason); };
    const std::size_t eq = setting.find('=');
    if (eq == std::string::npos) throw fail("expected PATH=SPEC, e.g. supports[0].position=0.5:1:11");
    SweepAxis axis;
    axis.setting = setting;
    axis.path = resolve_setting_path("--set", setting, c);
    const std::string spec = setting.substr(eq + 1);
    try {
        axis.values = parse_range_spec(spec, case_path_dimension(axis.path));
    } catch (const std::invalid_argument& e) {
        throw fail(e.what());
    }
    if (is_integer_path(axis.path)) {
        for (double v : axis.values) {
            if (v != std::floor(v) || std::abs(v) > INT_MAX) {
                throw fail(axis.path.text() + " takes whole numbers, got " + round_trip_text(v));
            }
        }
    }
    return axis;
}

SweepGrid::SweepGrid(std::vector<SweepAxis> axes) : axes_(std::move(axes)) {
    size_ = axes_.empty() ? 0 : 1;
    for (std::size_t a = 0; a < axes_.size(); ++a) {
        for (std::size_t b = 0; b < a; ++b) {
            if (axes_[a].path == axes_[b].path) {
                throw InputError("--set", axes_[a].setting,
                                 axes_[a].path.text() + " is already swept by --set " + axes_[b].setting);
            }
        }
        const std::size_t n = axes_[a].values.size();
        if (n == 0) throw InputError("--set", axes_[a].setting, "empty range");
        if (size_ > kMaxPoints / n) {
            throw InputError("--set", axes_[a].setting,
                             "the grid would have more than " + std::to_string(kMaxPoints) + " points");
        }
        size_ *= n;
    }
}

SweepGrid SweepGrid::paired(std::vector<SweepAxis> axes) {
    for (const SweepAxis& a : axes) {
        if (a.values.size() != axes.front().values.size()) {
            throw InputError(a.setting + ": " + std::to_string(a.values.size()) + " values where " +
                             axes.front().setting + " has " + std::to_string(axes.front().values.size()));
        }
    }
    // One value per axis gives the checks of a grid (repeated paths, empty axes) at no cost.
    std::vector<SweepAxis> firsts = axes;
    for (SweepAxis& a : firsts) a.values.resize(std::min<std::size_t>(a.values.size(), 1));
    SweepGrid g(std::move(firsts));
    g.axes_ = std::move(axes);
    g.size_ = g.axes_.empty() ? 0 : g.axes_.front().values.size();
    if (g.size_ > kMaxPoints) throw InputError("more than " + std::to_string(kMaxPoints) + " samples");
    g.paired_ = true;
    return g;
}

std::vector<double> SweepGrid::values_at(std::size_t index) const {
    if (index >= size_) throw std::out_of_range("SweepGrid: point index out of range");
    std::vector<double> v(axes_.size());
    if (paired_) {
        for (std::size_t a = 0; a < axes_.size(); ++a) v[a] = axes_[a].values[index];
        return v;
    }
    for (std::size_t a = axes_.size(); a-- > 0;) {
        const std::size_t n = axes_[a].values.size();
        v[a] = axes_[a].values[index % n];
        index /= n;
    }
    return v;
}

Case SweepGrid::case_at(const Case& base, std::size_t index) const {
    Case c = base;
    const std::vector<double> v = values_at(index);
    for (std::size_t a = 0; a < axes_.size(); ++a) set_case_value(c, axes_[a].path, v[a]);
    return c;
}

SweepGrid parse_sweep_grid(const std::vector<std::string>& settings, const Case& c) {
    if (settings.empty()) throw InputError("--set: at least one PATH=SPEC is needed");
    std::vector<SweepAxis> axes;
    axes.reserve(settings.size());
    for (const std::string& s : settings) axes.push_back(parse_sweep_setting(s, c));
    return SweepGrid(std::move(axes));
}

}  // namespace vi
