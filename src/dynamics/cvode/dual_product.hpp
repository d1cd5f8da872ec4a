#pragma once
// A x and A y in one pass over a dense column-major A: on a full basis of a fine mesh A is megabytes,
// and reading it once instead of twice is what these products cost. (Eigen's product by an n x 2
// matrix packs all of A first, a copy per call.) Internal to the CVODE solver.

#include <Eigen/Dense>

namespace vi::cvode_detail {

inline void dual_product(const Eigen::MatrixXd& A, const double* x, const double* y, Eigen::Ref<Eigen::VectorXd> ax,
                         Eigen::Ref<Eigen::VectorXd> ay) {
    ax.setZero();
    ay.setZero();
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
        // The column stays in the first-level cache between the two updates.
        ax.noalias() += x[j] * A.col(j);
        ay.noalias() += y[j] * A.col(j);
    }
}

}  // namespace vi::cvode_detail
