#include "dynamics/cvode/dual_product.hpp"

namespace vi::cvode_detail {

// Also built for AVX2 and AVX-512 (chosen at load time), without fused multiply-adds
// (-ffp-contract=off for this file): each entry is the same sum of the same products in every build.
__attribute__((target_clones("avx512f", "avx2", "default")))
void dual_product(const double* A, long rows, long cols, const double* x, const double* y, double* __restrict ax,
                  double* __restrict ay) {
    for (long i = 0; i < rows; ++i) {
        ax[i] = 0.0;
        ay[i] = 0.0;
    }
    for (long j = 0; j < cols; ++j) {
        // The column stays in the first-level cache between the two updates.
        const double* __restrict a = A + j * rows;
        const double xj = x[j], yj = y[j];
        for (long i = 0; i < rows; ++i) {
            ax[i] += xj * a[i];
            ay[i] += yj * a[i];
        }
    }
}

}  // namespace vi::cvode_detail
