#include "plot/beam_animation.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace vi {
namespace {

// 6 significant digits: a frame drawn a few hundred pixels high shows no more, and the page stays small.
double rounded(double v) {
    if (v == 0.0 || !std::isfinite(v)) return v;
    const double scale = std::pow(10.0, 5 - static_cast<int>(std::floor(std::log10(std::fabs(v)))));
    return std::round(v * scale) / scale;
}

}  // namespace

std::string beam_animation_json(const BeamField& f, const std::vector<std::pair<double, double>>& surfaces) {
    if (f.frames.empty()) throw std::invalid_argument("beam animation: the field has no frames");
    const std::size_t total = f.frames.size();
    const std::size_t n = std::min(total, kMaxPageFrames);
    nlohmann::json j;
    j["x"] = f.x;
    nlohmann::json t = nlohmann::json::array(), v = nlohmann::json::array();
    for (std::size_t i = 0; i < n; ++i) {
        const BeamFrame& fr = f.frames[n == 1 ? 0 : i * (total - 1) / (n - 1)];
        t.push_back(fr.t);
        nlohmann::json row = nlohmann::json::array();
        for (double d : fr.v) row.push_back(rounded(d));
        v.push_back(std::move(row));
    }
    j["t"] = t;
    j["v"] = v;
    nlohmann::json s = nlohmann::json::array();
    for (const auto& [x, h] : surfaces) s.push_back({x, h});
    j["surfaces"] = s;
    return j.dump();
}

}  // namespace vi
