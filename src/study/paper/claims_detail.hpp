#pragma once
// Pieces shared by the claims' source files (paper_claims*.cpp); not a stable interface.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "study/paper/curve_features.hpp"
#include "study/paper/claims.hpp"
#include "model/number_format.hpp"

namespace vi::claims_detail {

inline std::string pct(double v) {
    if (v != 0.0 && std::abs(v) < 1e-3) return formatted("%.1e %%", 100.0 * v);
    return decimals(100.0 * v, 1) + " %";
}

// The verdict on "a minimum of the curve lies at the paper's point p".
inline Verdict at_point(const std::optional<CurveMinimum>& m, double p) {
    if (!m) return Verdict::disagrees;
    const double d = std::abs(m->x - p);
    if (d <= kPointTolerance) return Verdict::agrees;
    if (d <= 2.0 * kPointTolerance) return Verdict::partly;
    return Verdict::disagrees;
}

inline std::string minima_list(const std::vector<CurveMinimum>& minima, int places) {
    if (minima.empty()) return "none";
    std::string s;
    for (const CurveMinimum& m : minima) s += (s.empty() ? "" : ", ") + decimals(m.x, places);
    return s;
}

inline const TransientPoint* point_at(const TransientScan& s, double x) {
    for (const TransientPoint& p : s.points) {
        if (std::abs(p.x - x) < 1e-9) return &p;
    }
    return nullptr;
}

inline std::optional<double> median(std::vector<double> v) {
    if (v.empty()) return std::nullopt;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// (max - min) / median of the valued samples.
inline std::optional<double> spread(const std::vector<std::optional<double>>& y) {
    std::vector<double> v;
    for (const auto& a : y) {
        if (a) v.push_back(*a);
    }
    const auto med = median(v);
    if (!med || *med == 0.0) return std::nullopt;
    return (*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end())) / *med;
}

template <class F>
std::vector<std::optional<double>> series(const TransientScan& s, F f) {
    std::vector<std::optional<double>> y;
    for (const TransientPoint& p : s.points) y.push_back(p.ok() ? f(p) : std::nullopt);
    return y;
}

// The claims about prestress (Fig. 9), impacts (Figs. 10, 11) and the period T (Fig. 3).
void impact_claims(const PaperStudy& st, std::vector<Claim>& out);

}  // namespace vi::claims_detail
