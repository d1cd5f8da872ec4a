#pragma once
// A x and A y in one pass over a dense column-major A: on a full basis of a fine mesh A is megabytes,
// and reading it once instead of twice is what these products cost. (Eigen's product by an n x 2
// matrix packs all of A first, a copy per call.) Internal to the CVODE solver.

#include <Eigen/Dense>

namespace vi::cvode_detail {

// ax = A x and ay = A y for the rows x cols column-major A (leading dimension rows): each entry
// summed over the columns in order, as ax += x_j A(:, j) forms it, rounding alike on every processor.
void dual_product(const double* A, long rows, long cols, const double* x, const double* y, double* ax, double* ay);

inline void dual_product(const Eigen::MatrixXd& A, const double* x, const double* y, Eigen::Ref<Eigen::VectorXd> ax,
                         Eigen::Ref<Eigen::VectorXd> ay) {
    dual_product(A.data(), A.rows(), A.cols(), x, y, ax.data(), ay.data());
}

}  // namespace vi::cvode_detail
