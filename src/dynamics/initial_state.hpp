#pragma once
// Static contact problems on the bending DOFs: the equilibrium the beam rests in and the static step
// (a point force lifting one point) the transient starts from (paper, section 3), plus the initial
// velocity field.

#include <Eigen/Dense>
#include <vector>

#include "dynamics/transient_problem.hpp"
#include "model/case.hpp"

namespace vi {

// A static state and its contact set. Statically a contact pushes with F = Kc d, so contact k is
// closed (active) exactly when its penetration d_k = sign_k (surface_k - q[dof_k]) is positive.
struct StaticContactState {
    Eigen::VectorXd q;         // bending DOFs [m, rad]
    std::vector<bool> active;  // one flag per contact
};

// Solves K q = f + sum over active k of Kc_k (surface_k - q[dof_k]) e_k with active = {k : d_k > 0}:
// an active-set iteration (closing contacts that penetrate, opening those that would pull) from
// `start`, or when start is empty from the contacts that push at q = 0 (prestressed ones). Throws
// std::runtime_error("static contact problem did not converge") after 2^k + 10 iterations, or when
// K with the closed contacts is not positive definite.
StaticContactState solve_static_contact(const Eigen::MatrixXd& K, const std::vector<ContactElement>& contacts,
                                        const Eigen::VectorXd& f, std::vector<bool> start = {});

// The static state lifted by a point force P along `shape` (the consistent load vector of a unit
// force at the point, so that shape . q is v at the point) such that shape . q = target.
struct PointStep {
    StaticContactState state;
    double force = 0.0;  // P [N]
};

// The contact problem is piecewise linear in P: for a guessed contact set it solves for the
// unit-force response u and the contact-only response w, takes P = (target - shape.w) / (shape.u),
// checks the contact set at q = P u + w and repeats (from `start`). Same limits and errors as
// solve_static_contact.
PointStep solve_static_lift(const Eigen::MatrixXd& K, const std::vector<ContactElement>& contacts,
                            const Eigen::VectorXd& shape, double target, std::vector<bool> start);

// How the transient starts.
struct InitialConditions {
    StaticContactState equilibrium;  // no static load: prestressed supports may push
    StaticContactState stepped;      // q0 and the contacts closed at t = 0
    Eigen::VectorXd v0;              // initial velocity [m/s, rad/s]
    double force = 0.0;              // static point force of the step [N]
    double lift = 0.0;               // v at the point, stepped minus equilibrium [m]
};

// The equilibrium, the static step of init (rest, displacement or force at init.position) and the
// initial velocity. shape: unit point load at init.position over the bending DOFs; is_v: which
// bending DOFs are transverse; mode: the mass-normalised unsupported bending mode init.velocity_mode
// (used only for Velocity::mode). Throws InputError naming initial.displacement (or initial.force)
// when the step pushes the point into a support that does not touch at equilibrium, and naming
// initial.velocity_mode when that mode does not move at the point.
InitialConditions initial_conditions(const InitialState& init, const Eigen::MatrixXd& K,
                                     const std::vector<ContactElement>& contacts, const Eigen::VectorXd& shape,
                                     const std::vector<bool>& is_v, const Eigen::VectorXd& mode);

}  // namespace vi
