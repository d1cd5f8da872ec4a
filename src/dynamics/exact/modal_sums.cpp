#include "dynamics/exact/modal_sums.hpp"

namespace vi {

// Also built for AVX2 and AVX-512 (chosen at load time), without fused multiply-adds
// (-ffp-contract=off for this file): the same rounding in every build, as with two lanes.
__attribute__((target_clones("avx512f", "avx2", "default")))
void add_mode_columns(const double* vr, const double* vi, long ld, int n, const int* col, const double* coef,
                      int count, double* head, double* tail) {
    for (int j = 0; j < count; ++j) {
        const double* a = vr + col[j] * ld;
        const double* b = vi + col[j] * ld;
        const double wr = coef[4 * j], wi = coef[4 * j + 1], lr = coef[4 * j + 2], li = coef[4 * j + 3];
        for (int i = 0; i < n; ++i) {
            const double x = a[i], y = b[i];
            head[i] += wr * x - wi * y;
            tail[i] += lr * x - li * y;
        }
    }
}

// Vectorised across the samples of the run (each sum over the modes stays in mode order).
__attribute__((target_clones("avx512f", "avx2", "default")))
void add_channel_runs(const double* pack, int nf, const int* live, int nl, const double* er, const double* ei, int S,
                      double* acc) {
    for (long i = 0; i < static_cast<long>(nf) * S; ++i) acc[i] = 0.0;
    for (int l = 0; l < nl; ++l) {
        const double* ar = pack + 2 * static_cast<long>(nf) * live[l];
        const double* ai = ar + nf;
        const double* xr = er + static_cast<long>(l) * S;
        const double* xi = ei + static_cast<long>(l) * S;
        for (int j = 0; j < nf; ++j) {
            const double a = ar[j], b = ai[j];
            double* out = acc + static_cast<long>(j) * S;
            for (int s = 0; s < S; ++s) out[s] += a * xr[s] - b * xi[s];
        }
    }
}

}  // namespace vi
