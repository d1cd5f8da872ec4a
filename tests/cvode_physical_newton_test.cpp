// The Newton solve of a full modal basis in the FE DOFs (dynamics/cvode/physical_newton.*) against
// the same system assembled and solved densely in modal coordinates: an electrode's tangent over
// most of the beam, several step sizes, random right-hand sides.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_system.hpp"
#include "dynamics/cvode/dual_product.hpp"
#include "dynamics/cvode/modal_basis.hpp"
#include "dynamics/cvode/physical_newton.hpp"
#include "dynamics/transient_start.hpp"
#include "io/case_reader.hpp"

namespace vi {
namespace {

// The dual product (built for the processor's widest vectors) gives each entry as x_j A(:, j) summed
// column by column in order gives it, to the last bit, at sizes that leave remainders of every width.
TEST(DualProduct, EveryEntryIsTheColumnSumInOrderBitForBit) {
    std::mt19937 rng(3);
    std::normal_distribution<double> n(0.0, 1.0);
    for (const auto& [rows, cols] : std::vector<std::pair<int, int>>{{1, 1}, {7, 3}, {33, 17}, {130, 101}}) {
        Eigen::MatrixXd A(rows, cols);
        std::vector<double> x(static_cast<std::size_t>(cols)), y(x.size());
        for (Eigen::Index k = 0; k < A.size(); ++k) A.data()[k] = n(rng) * std::exp(10.0 * n(rng));
        for (std::size_t j = 0; j < x.size(); ++j) {
            x[j] = n(rng);
            y[j] = n(rng) * 1e-3;
        }
        Eigen::VectorXd ax(rows), ay(rows);
        cvode_detail::dual_product(A, x.data(), y.data(), ax, ay);
        for (int i = 0; i < rows; ++i) {
            double sx = 0.0, sy = 0.0;
            for (int j = 0; j < cols; ++j) {
                sx += x[static_cast<std::size_t>(j)] * A(i, j);
                sy += y[static_cast<std::size_t>(j)] * A(i, j);
            }
            EXPECT_EQ(ax[i], sx) << rows << " x " << cols << ", row " << i;
            EXPECT_EQ(ay[i], sy) << rows << " x " << cols << ", row " << i;
        }
    }
}

using cvode_detail::ModalSystem;
using cvode_detail::PhysicalNewton;

// The elements' tangents summed onto the union of their DOFs (s x s each).
void union_tangents(const ModalSystem& sys, const std::vector<Eigen::MatrixXd>& dfdq,
                    const std::vector<Eigen::MatrixXd>& dfdv, Eigen::MatrixXd& Fq, Eigen::MatrixXd& Fv) {
    const Eigen::Index s = sys.union_rows().rows();
    Fq = Eigen::MatrixXd::Zero(s, s);
    Fv = Eigen::MatrixXd::Zero(s, s);
    for (int e = 0; e < sys.elements(); ++e) {
        const std::vector<int>& at = sys.union_positions(e);
        const std::size_t ue = static_cast<std::size_t>(e);
        for (std::size_t i = 0; i < at.size(); ++i)
            for (std::size_t j = 0; j < at.size(); ++j) {
                Fq(at[i], at[j]) += dfdq[ue](static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
                Fv(at[i], at[j]) += dfdv[ue](static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
            }
    }
}

TEST(CvodePhysicalNewton, SolvesTheModalNewtonSystemOfAnElectrode) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch.toml");
    c.beam.elements = 20;
    const BuiltProblem built = build_transient_problem(c);
    const TransientProblem& p = built.problem;
    ModalSystem sys(p, full_basis(p.K, p.M));
    ASSERT_EQ(sys.basis_size(), p.size());
    // Halfway down the gap the electrostatic tangent is well away from zero.
    Eigen::VectorXd y = sys.initial_state();
    y.head(sys.basis_size()) += 0.3 * sys.basis().phi.transpose() * (p.M * Eigen::VectorXd::Constant(p.size(), -1e-6));
    sys.set_modes(sys.initial_modes(y.data()));
    std::vector<Eigen::MatrixXd> dfdq, dfdv;
    sys.tangents(1e-7, y.data(), dfdq, dfdv);
    Eigen::MatrixXd Fq, Fv;
    union_tangents(sys, dfdq, dfdv, Fq, Fv);
    ASSERT_GT(Fq.cwiseAbs().maxCoeff(), 0.0);

    // The FE-DOF form stands on phi^T M phi = I; the dense eigen solve holds it to about 1e-9 here,
    // and the solutions agree to that times the spread of the Newton matrix's diagonal (measured
    // 4e-10 at gamma = 1e-12, 1.5e-9 at 1e-9, 8e-9 at 1e-7): 1e-7 is that with a margin, far below
    // what Newton's iteration needs of its matrix.
    const Eigen::MatrixXd& phi = sys.basis().phi;
    const Eigen::MatrixXd unit = phi.transpose() * (p.M * phi);
    ASSERT_LT((unit - Eigen::MatrixXd::Identity(unit.rows(), unit.cols())).norm(), 1e-8);
    PhysicalNewton newton(sys);
    newton.set_tangents(Fq, Fv, sys.union_dofs());
    const Eigen::MatrixXd& P = sys.union_rows();
    const Eigen::VectorXd& w = sys.basis().omega;
    const Eigen::VectorXd D = (p.alpha + p.beta * w.array().square()).matrix();
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    const int r = sys.basis_size();
    // gamma from a step far below the first period to one near the highest mode's.
    for (const double gamma : {1e-12, 1e-9, 1e-7}) {
        const double a = -gamma, b = 1.0;
        ASSERT_TRUE(newton.factor(a, b));
        Eigen::MatrixXd full = P.transpose() * (-a * a * Fq + a * b * Fv) * P;
        full.diagonal() += (b * b + a * a * w.array().square() - a * b * D.array()).matrix();
        for (int trial = 0; trial < 3; ++trial) {
            Eigen::VectorXd r_eta(r), r_v(r);
            for (int k = 0; k < r; ++k) {
                r_eta[k] = normal(rng);
                r_v[k] = w[k] * normal(rng);
            }
            const Eigen::VectorXd t = b * r_v + a * w.cwiseAbs2().cwiseProduct(r_eta) - a * (P.transpose() * (Fq * (P * r_eta)));
            const Eigen::VectorXd expected = full.partialPivLu().solve(t);
            // The electrode's part is well above the tolerance below at the largest step: without it
            // the answer differs by more than 1e-5 there.
            const Eigen::VectorXd bare = (b * r_v + a * w.cwiseAbs2().cwiseProduct(r_eta))
                                             .cwiseQuotient((b * b + a * a * w.array().square() - a * b * D.array()).matrix());
            if (gamma > 1e-8) {
                EXPECT_GT((bare - expected).norm(), 1e-5 * expected.norm());
            }
            Eigen::VectorXd xv;
            newton.solve(r_eta, r_v, xv);
            EXPECT_LT((xv - expected).norm(), 1e-7 * expected.norm()) << "gamma " << gamma << ", trial " << trial;
        }
    }
}

}  // namespace
}  // namespace vi
