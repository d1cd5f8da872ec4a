#pragma once
// Small transient problems built directly (without a case file) for solver tests: the library's
// reference problems, and the pieces of one-DOF problems (a mass on a spring, a support, a load).

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/transient_problem.hpp"
#include "forces/kelvin_voigt_contact.hpp"
#include "forces/point_load_element.hpp"
#include "paper_cases.hpp"
#include "validation/reference_problems.hpp"

namespace vi::test {

using vi::cantilever_drop;
using vi::single_dof_drop;

// One DOF of mass m [kg] on a spring k [N/m] (0: none), at rest at 0 and watched; no force yet.
inline TransientProblem one_dof(double m, double k) {
    TransientProblem p;
    p.M = Eigen::MatrixXd::Constant(1, 1, m).sparseView();
    p.K = Eigen::MatrixXd::Constant(1, 1, k).sparseView();
    p.q0 = p.v0 = Eigen::VectorXd::Zero(1);
    p.watched_dof = 0;
    return p;
}

// A Kelvin-Voigt support "supports[index]" on `dof`: below (sign +1) or above (-1) with its surface
// at `surface` [m], Kc [N/m], Cc [N s/m], at x [m].
inline ForceElementPtr support(int index, int dof, double sign, double surface, double stiffness, double damping,
                               double x = 0.0) {
    return std::make_shared<KelvinVoigtContact>("supports[" + std::to_string(index) + "]", dof, sign, surface,
                                                stiffness, damping, x);
}

// A point load "loads[0]" F g(t) [N] on DOF 0.
inline ForceElementPtr load_on_first_dof(double force, const TimeFunction& g) {
    return std::make_shared<PointLoadElement>("loads[0]", std::vector<int>{0}, std::vector<double>{1.0}, force, g, -1.0);
}

}  // namespace vi::test
