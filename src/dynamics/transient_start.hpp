#pragma once
// How a transient starts (paper, section 3), apart from the model it runs on: the equilibrium, the
// static step, the release at t = 0 with its velocity field, the horizon and the output step. And
// the TransientProblem a solver takes: a model with a start.

#include <Eigen/Dense>
#include <vector>

#include "dynamics/transient_problem.hpp"
#include "model/case.hpp"
#include "problem/beam_model.hpp"

namespace vi {

struct TransientStart {
    Eigen::VectorXd q0;             // displacement at t = 0 [m, rad]
    Eigen::VectorXd v0;             // velocity at t = 0 [m/s, rad/s]
    std::vector<int> modes0;        // each element's mode at t = 0
    Eigen::VectorXd q_equilibrium;  // static equilibrium over the bending DOFs [m, rad]
    double y0_m = 0.0;              // lift of the point at initial.position above equilibrium [m]
    double static_force_n = 0.0;    // static point force of the step [N] (0 at rest)
    double t_end = 0.0;             // horizon [s]
    double output_step = 0.0;       // sampling step of the time history [s]
};

// The start c.initial and c.solver describe, on model m. Throws InputError naming the key when the
// step is impossible (it presses the beam into a support, a velocity mode with a nodal point at
// initial.position).
TransientStart transient_start(const Case& c, const BeamModel& m);

// The problem a transient solver takes: m's matrices, damping and elements, with start s.
TransientProblem transient_problem(const BeamModel& m, const TransientStart& s);

// A model, a start and the problem they make.
struct BuiltProblem {
    BeamModel model;
    TransientStart start;
    TransientProblem problem;
};

// build_beam_model(c), transient_start, transient_problem.
BuiltProblem build_transient_problem(const Case& c);

}  // namespace vi
