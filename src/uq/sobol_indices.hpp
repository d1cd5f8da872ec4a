#pragma once
// First-order and total Sobol indices from Saltelli's sampling scheme: two independent sample
// matrices A and B of N rows, and for each input i the matrix A_B^(i), A with its column i taken
// from B; N (d + 2) model runs for d inputs (docs/uq.md).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "uq/statistics.hpp"

namespace vi {

// The smallest N the estimators are run with: below it the bootstrap's percentile intervals of the
// indices rest on too few distinct rows to mean anything.
inline constexpr std::size_t kMinSobolBaseSamples = 32;

struct SobolIndex {
    double first = 0.0;  // S_i = V[E(Y | X_i)] / V(Y)
    double total = 0.0;  // S_Ti = E[V(Y | X_~i)] / V(Y)
    Interval first_ci, total_ci;
    bool has_ci = false;  // the bootstrap gave both intervals
};

struct SobolEstimate {
    std::size_t rows = 0;   // base rows used: those with every run's value present
    double variance = 0.0;  // V(Y) from the f(A) and f(B) of those rows
    std::vector<SobolIndex> inputs;  // one per input, in order; empty when rows < 2 or V(Y) is at
                                     // rounding level (SD below 1e-12 of the mean's magnitude)
};

// The Saltelli (2010) estimator of S_i, (1/N) sum_j (f(B)_j - f0) (f(A_B^i)_j - f(A)_j) / V with f0
// the mean of f(A) and f(B) (centring as Sobol' 2001 advises: the same expectation, a variance free
// of f0^2), and
// Jansen's (1999) of S_Ti, (1/2N) sum_j (f(A)_j - f(A_B^i)_j)^2 / V (Saltelli et al. 2010, Table 2,
// (b) and (f)), V the variance of the 2N values of f(A) and f(B). fA and fB hold N values, fAB one
// vector of N per input; a base row j with a NaN in any of its d + 2 values is left out of all.
// Percentile bootstrap intervals at `confidence` from `resamples` resamples of the rows (seeded).
SobolEstimate sobol_indices(const std::vector<double>& fA, const std::vector<double>& fB,
                            const std::vector<std::vector<double>>& fAB, std::size_t resamples, std::uint64_t seed,
                            double confidence);

}  // namespace vi
