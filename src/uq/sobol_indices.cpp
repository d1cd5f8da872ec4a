#include "uq/sobol_indices.hpp"

#include <cmath>
#include <cstdint>

namespace vi {
namespace {

// The values of the kept rows, one vector per matrix: A, B, then A_B^(i).
struct Runs {
    std::vector<double> a, b;
    std::vector<std::vector<double>> ab;
};

// V(Y), S_i and S_Ti over the rows `rows` of `r` (indices into the kept rows, repeats allowed), for
// every input or only for input `only` (the others then NaN).
struct Point {
    double variance = 0.0;
    std::vector<double> first, total;
};

Point estimate(const Runs& r, const std::vector<std::size_t>& rows, std::size_t only = SIZE_MAX) {
    const double n = static_cast<double>(rows.size());
    double mean = 0.0;
    for (std::size_t j : rows) mean += r.a[j] + r.b[j];
    mean /= 2.0 * n;
    double var = 0.0;
    for (std::size_t j : rows) var += (r.a[j] - mean) * (r.a[j] - mean) + (r.b[j] - mean) * (r.b[j] - mean);
    Point p;
    p.variance = var / (2.0 * n - 1.0);
    // The outputs centred on their mean (Sobol' 2001): the first-order sum's expectation is the same,
    // and its variance no longer grows with the squared mean, which would swamp it for a quantity
    // whose spread is a few percent of its value (a pull-in voltage).
    for (std::size_t i = 0; i < r.ab.size(); ++i) {
        if (only != SIZE_MAX && i != only) {
            p.first.push_back(std::nan(""));
            p.total.push_back(std::nan(""));
            continue;
        }
        const std::vector<double>& ab = r.ab[i];
        double vi = 0.0, vti = 0.0;
        for (std::size_t j : rows) {
            vi += (r.b[j] - mean) * (ab[j] - r.a[j]);
            vti += (r.a[j] - ab[j]) * (r.a[j] - ab[j]);
        }
        p.first.push_back(vi / n / p.variance);
        p.total.push_back(0.5 * vti / n / p.variance);
    }
    return p;
}

}  // namespace

SobolEstimate sobol_indices(const std::vector<double>& fA, const std::vector<double>& fB,
                            const std::vector<std::vector<double>>& fAB, std::size_t resamples, std::uint64_t seed,
                            double confidence) {
    Runs r;
    r.ab.resize(fAB.size());
    for (std::size_t j = 0; j < fA.size(); ++j) {
        bool present = !std::isnan(fA[j]) && !std::isnan(fB[j]);
        for (const std::vector<double>& ab : fAB) present = present && !std::isnan(ab[j]);
        if (!present) continue;
        r.a.push_back(fA[j]);
        r.b.push_back(fB[j]);
        for (std::size_t i = 0; i < fAB.size(); ++i) r.ab[i].push_back(fAB[i][j]);
    }
    SobolEstimate out;
    out.rows = r.a.size();
    if (out.rows < 2) return out;
    std::vector<std::size_t> all(out.rows);
    for (std::size_t j = 0; j < all.size(); ++j) all[j] = j;
    const Point p = estimate(r, all);
    out.variance = p.variance;
    // A spread at the level of rounding (relative SD below 1e-12: a quantity the inputs do not
    // change) has no indices: their ratios would be of rounding noise.
    double mean = 0.0;
    for (std::size_t j : all) mean += 0.5 * (r.a[j] + r.b[j]) / static_cast<double>(out.rows);
    if (!(p.variance > 1e-24 * mean * mean)) return out;
    for (std::size_t i = 0; i < fAB.size(); ++i) {
        SobolIndex s;
        s.first = p.first[i];
        s.total = p.total[i];
        // One stream per input and kind, so that an index's interval does not depend on the others.
        const auto of = [&](bool total) {
            return [&, total](const std::vector<std::size_t>& rows) {
                const Point q = estimate(r, rows, i);
                return q.variance > 0.0 ? (total ? q.total[i] : q.first[i]) : std::nan("");
            };
        };
        const auto first_ci = bootstrap_interval(out.rows, resamples, derived_seed(seed, 2 * i), confidence, of(false));
        const auto total_ci = bootstrap_interval(out.rows, resamples, derived_seed(seed, 2 * i + 1), confidence, of(true));
        if (first_ci && total_ci) {
            s.first_ci = *first_ci;
            s.total_ci = *total_ci;
            s.has_ci = true;
        }
        out.inputs.push_back(s);
    }
    return out;
}

}  // namespace vi
