#pragma once
// Small transient problems built directly (without a case file) for solver tests.

#include <cmath>

#include "dynamics/transient_problem.hpp"
#include "fem/system.hpp"
#include "paper_cases.hpp"

namespace vi::test {

// One mass m [kg] on a contact below at height 0, starting at height h with velocity -v.
// The free state needs a positive stiffness; k0 = 1e-14 Kc changes the contact closed forms by
// O(1e-14), far below the tolerances checked.
inline TransientProblem single_dof_drop(double m, double Kc, double Cc, double h, double v, double t_end) {
    TransientProblem p;
    p.M = Eigen::MatrixXd::Constant(1, 1, m);
    p.K = Eigen::MatrixXd::Constant(1, 1, 1e-14 * Kc);
    ContactElement c;
    c.dof = 0;
    c.stiffness = Kc;
    c.damping = Cc;
    p.contacts.push_back(c);
    p.q0 = Eigen::VectorXd::Constant(1, h);
    p.v0 = Eigen::VectorXd::Constant(1, -v);
    p.active0 = {false};
    p.tip_dof = 0;
    p.t_end = t_end;
    p.output_step = t_end / 100;
    return p;
}

// The paper's cantilever (m elements) with a Kelvin-Voigt support at its tip, zero gap, released
// from a static tip lift y0; alpha, beta are the Rayleigh coefficients.
inline TransientProblem cantilever_drop(int m, double Kc, double Cc, double y0, double alpha, double beta,
                                        double t_end) {
    const Case c = paper_cantilever(m, 1.0);
    const System s = build_system(c);
    TransientProblem p;
    p.M = Eigen::MatrixXd(submatrix(s.M, s.bending));
    p.K = Eigen::MatrixXd(submatrix(s.K, s.bending));
    p.alpha = alpha;
    p.beta = beta;
    const int tip_reduced = s.reduced_of[global_dof(s.mesh.node_count() - 1, 1)];
    int tip = -1;
    for (std::size_t i = 0; i < s.bending.size(); ++i) {
        if (s.bending[i] == tip_reduced) tip = static_cast<int>(i);
    }
    Eigen::VectorXd f = Eigen::VectorXd::Zero(p.K.rows());
    f[tip] = 1.0;
    Eigen::VectorXd q = p.K.ldlt().solve(f);
    q *= y0 / q[tip];
    ContactElement ce;
    ce.dof = tip;
    ce.stiffness = Kc;
    ce.damping = Cc;
    ce.x = c.beam.length;
    p.contacts.push_back(ce);
    p.q0 = q;
    p.v0 = Eigen::VectorXd::Zero(q.size());
    p.active0 = {false};
    p.tip_dof = tip;
    p.t_end = t_end;
    p.output_step = t_end / 500;
    return p;
}

}  // namespace vi::test
