// An electrode evaluated on a reduced basis (ForceElement::reduced) against the pad's own force and
// tangent at q = P eta projected onto the basis: the same quadrature, so equal to roundoff; and the
// reduced CVODE model's right-hand side against the projection of every element's force.

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_system.hpp"
#include "dynamics/cvode/modal_basis.hpp"
#include "dynamics/transient_start.hpp"
#include "forces/force_assembly.hpp"
#include "io/case_reader.hpp"

namespace vi {
namespace reduced_pad_test {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct Setup {
    BuiltProblem built;
    Eigen::MatrixXd phi;  // a few modes of the beam
};

// The switch example at m = 40 with `fringing`, and 6 modes of it.
Setup setup(const std::string& fringing) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch.toml");
    c.beam.elements = 40;
    c.electrodes.at(0).fringing = fringing == "none" ? Fringing::none : Fringing::meijs_fokkema;
    Setup s{build_transient_problem(c), {}};
    s.phi = full_basis(s.built.problem.K, s.built.problem.M).phi.leftCols(6);
    return s;
}

void check_pad(const std::string& fringing) {
    const Setup s = setup(fringing);
    const TransientProblem& p = s.built.problem;
    const ForceElement* pad = nullptr;
    for (const ForceElementPtr& e : p.forces)
        if (e->stored_energy_kind() == StoredEnergyKind::electrical) pad = e.get();
    ASSERT_NE(pad, nullptr);
    const std::vector<int>& dofs = pad->dofs();
    Eigen::MatrixXd P(static_cast<Eigen::Index>(dofs.size()), s.phi.cols());
    for (std::size_t k = 0; k < dofs.size(); ++k) P.row(static_cast<Eigen::Index>(k)) = s.phi.row(dofs[k]);
    const auto on_basis = pad->reduced(BasisRows{P.data(), dofs.size(), static_cast<std::size_t>(P.cols())});
    ASSERT_NE(on_basis, nullptr);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Eigen::Index r = P.cols();
    for (int trial = 0; trial < 4; ++trial) {
        // A deflection toward the electrode of up to 0.8 um at the watched point (0.4 of the gap).
        Eigen::VectorXd eta(r), eta_dot = Eigen::VectorXd::Zero(r);
        for (Eigen::Index k = 0; k < r; ++k) eta[k] = u(rng);
        eta *= 0.8e-6 * (0.25 + 0.25 * trial) / (s.phi.row(p.watched_dof) * eta).cwiseAbs().sum();
        const Eigen::VectorXd q = P * eta;
        const Eigen::VectorXd v = Eigen::VectorXd::Zero(q.size());
        const ElementState es{1e-7, q.data(), v.data(), nullptr};
        const ReducedState rs{1e-7, eta.data(), eta_dot.data()};

        std::vector<double> f(dofs.size(), 0.0);
        pad->add_force(es, 0, f.data());
        const Eigen::VectorXd projected = P.transpose() * Eigen::Map<const Eigen::VectorXd>(f.data(), q.size());
        Eigen::VectorXd reduced = Eigen::VectorXd::Zero(r);
        EXPECT_EQ(on_basis->add_force_and_power(rs, 0, reduced.data()), 0.0);
        EXPECT_LT((reduced - projected).norm(), 1e-12 * projected.norm()) << fringing << " trial " << trial;

        RowMajor dfdq = RowMajor::Zero(q.size(), q.size()), dfdv = dfdq;
        pad->add_tangent(es, 0, dfdq.data(), dfdv.data());
        const Eigen::MatrixXd Kp = P.transpose() * dfdq * P;
        RowMajor Kq = RowMajor::Zero(r, r), Kv = Kq;
        on_basis->add_tangent(rs, 0, Kq.data(), Kv.data());
        EXPECT_LT((Eigen::MatrixXd(Kq) - Kp).norm(), 1e-12 * Kp.norm()) << fringing << " trial " << trial;
        EXPECT_EQ(Kv.norm(), 0.0);

        const double sw = pad->switching_function(es, 0);
        EXPECT_NEAR(on_basis->switching_function(rs, 0), sw, 1e-13 * std::max(1.0, std::abs(sw)));
        EXPECT_EQ(on_basis->input_power(rs, 0), pad->input_power(es, 0));
    }
}

TEST(ReducedPad, ForceAndTangentEqualTheProjectionParallelPlate) { check_pad("none"); }
TEST(ReducedPad, ForceAndTangentEqualTheProjectionWithFringing) { check_pad("meijs_fokkema"); }

// The reduced model's right-hand side, with the pad on the basis, against phi^T of the sum of every
// element's force at q = phi eta.
TEST(ReducedPad, ReducedModelRightHandSideEqualsTheProjection) {
    Case c = read_case_file(std::string(VI_SOURCE_DIR) + "/examples/switch/cantilever_switch.toml");
    c.beam.elements = 40;
    const BuiltProblem built = build_transient_problem(c);
    const TransientProblem& p = built.problem;
    std::vector<Eigen::VectorXd> loads;
    for (const ForceElementPtr& e : p.forces)
        for (const std::vector<double>& pattern : e->load_patterns()) {
            Eigen::VectorXd l = Eigen::VectorXd::Zero(p.size());
            for (std::size_t k = 0; k < pattern.size(); ++k) l[e->dofs()[k]] = pattern[k];
            loads.push_back(l);
        }
    const ModalBasis basis = reduced_basis(p.K, p.M, 6, loads, {p.q0, p.v0});
    ASSERT_FALSE(basis.full);
    cvode_detail::ModalSystem sys(p, basis);
    bool any = false;
    for (int e = 0; e < sys.elements(); ++e) any = any || sys.reduced(e);
    ASSERT_TRUE(any);
    const int r = sys.basis_size();
    Eigen::VectorXd y = sys.initial_state();
    y.head(r) += basis.phi.transpose() * (p.M * Eigen::VectorXd::Constant(p.size(), -0.5e-6));
    sys.set_modes(sys.initial_modes(y.data()));
    Eigen::VectorXd ydot(sys.size());
    const double t = 1e-7;
    sys.rhs(t, y.data(), ydot.data());

    const Eigen::VectorXd q = basis.phi * y.head(r), v = basis.phi * y.segment(r, r);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(p.size());
    ElementAssembler a;
    for (int e = 0; e < sys.elements(); ++e) {
        a.gather(sys.element(e), sys.element(e).dofs(), q.data(), v.data(), nullptr, t);
        a.force(sys.modes()[static_cast<std::size_t>(e)]);
        a.scatter_force(1.0, f);
    }
    const Eigen::ArrayXd w2 = basis.omega.array().square();
    const Eigen::VectorXd expected = (-w2 * y.head(r).array() - (p.alpha + p.beta * w2) * y.segment(r, r).array()).matrix() +
                                     basis.phi.transpose() * f;
    EXPECT_LT((ydot.segment(r, r) - expected).norm(), 1e-12 * expected.norm());

    // The projected tangent, against phi^T (sum of the elements' d f / d q) phi.
    std::vector<Eigen::MatrixXd> dfdq, dfdv;
    Eigen::MatrixXd mq, mv;
    sys.tangents(t, y.data(), dfdq, dfdv, &mq, &mv);
    ASSERT_EQ(mq.rows(), r);
    Eigen::MatrixXd K = mq;
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(r, r);
    for (int e = 0; e < sys.elements(); ++e) {
        const ForceElement& el = sys.element(e);
        a.gather(el, el.dofs(), q.data(), v.data(), nullptr, t);
        a.tangent(sys.modes()[static_cast<std::size_t>(e)]);
        const std::size_t m = el.dofs().size();
        Eigen::MatrixXd Pe(static_cast<Eigen::Index>(m), r);
        for (std::size_t k = 0; k < m; ++k) Pe.row(static_cast<Eigen::Index>(k)) = basis.phi.row(el.dofs()[k]);
        const Eigen::Map<const RowMajor> T(a.dfdq().data(), static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
        full += Pe.transpose() * T * Pe;
        if (!sys.reduced(e)) K += Pe.transpose() * dfdq[static_cast<std::size_t>(e)] * Pe;
    }
    EXPECT_LT((K - full).norm(), 1e-12 * full.norm());
}

}  // namespace reduced_pad_test
}  // namespace vi
