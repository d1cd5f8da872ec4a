#include "statics/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "model/input_error.hpp"

namespace vi {
namespace {

using Index = Eigen::Index;

std::string length_text(double v) {
    std::ostringstream s;
    s << v << " m";
    return s.str();
}

// The element's force at the static state q in `mode`, summed over its DOFs: the direction it
// pushes (a point contact acts on one DOF).
double push_direction(const ForceElement& e, const Eigen::VectorXd& q, int mode) {
    const std::vector<int>& d = e.dofs();
    std::vector<double> ql(d.size()), vl(d.size(), 0.0), f(d.size(), 0.0);
    for (std::size_t k = 0; k < d.size(); ++k) ql[k] = q[d[k]];
    e.add_force(ElementState{0.0, ql.data(), vl.data(), nullptr}, mode, f.data());
    double sum = 0.0;
    for (double x : f) sum += x;
    return sum;
}

double contact_penetration(const ForceElement& e, const Eigen::VectorXd& q) {
    const std::vector<int>& d = e.dofs();
    std::vector<double> ql(d.size()), vl(d.size(), 0.0);
    for (std::size_t k = 0; k < d.size(); ++k) ql[k] = q[d[k]];
    return e.contact_reading(ElementState{0.0, ql.data(), vl.data(), nullptr}).penetration;
}

}  // namespace

InitialConditions initial_conditions(const InitialState& init, const Eigen::SparseMatrix<double>& K,
                                     const ForceSet& forces, const Eigen::VectorXd& shape,
                                     const std::vector<bool>& is_v, const Eigen::VectorXd& mode, int max_iterations) {
    using Kind = InitialState::Kind;
    InitialConditions ic;
    ic.equilibrium = solve_static(K, forces, Eigen::VectorXd::Zero(K.rows()), {}, max_iterations);
    const double v_eq = shape.dot(ic.equilibrium.q);
    switch (init.kind) {
        case Kind::rest:
            ic.stepped = ic.equilibrium;
            break;
        case Kind::displacement: {
            StaticLift step =
                solve_static_lift(K, forces, shape, v_eq + init.displacement, ic.equilibrium.modes, max_iterations);
            ic.stepped = std::move(step.state);
            ic.force = step.force;
            break;
        }
        case Kind::force:
            ic.stepped = solve_static(K, forces, init.force * shape, ic.equilibrium.modes, max_iterations);
            ic.force = init.force;
            break;
    }
    ic.lift = shape.dot(ic.stepped.q) - v_eq;

    // A contact that closes during the step and pushes against the lift: the static force pressed
    // the beam into it (e.g. a tip lifted past the gap of a support above). Contacts already closed
    // at equilibrium (prestressed) and contacts on the far side are part of a valid state.
    const char* key = init.kind == Kind::force ? "initial.force" : "initial.displacement";
    for (std::size_t k = 0; k < forces.size(); ++k) {
        const ForceElement& e = *forces[k];
        if (!e.is_contact() || !e.in_static_state()) continue;
        const int m = ic.stepped.modes[k];
        if (m != e.contact_mode() || ic.equilibrium.modes[k] == e.contact_mode()) continue;
        if (push_direction(e, ic.stepped.q, m) * ic.lift >= 0.0) continue;
        throw InputError(std::string(key) + ": the initial state penetrates " + e.name() +
                         " (d = " + length_text(contact_penetration(e, ic.stepped.q)) +
                         "; a smaller step or a larger gap is needed)");
    }

    const Index n = K.rows();
    ic.v0 = Eigen::VectorXd::Zero(n);
    switch (init.velocity_kind) {
        case InitialState::Velocity::none: break;
        case InitialState::Velocity::uniform:
            for (Index i = 0; i < n; ++i) {
                if (is_v[static_cast<std::size_t>(i)]) ic.v0[i] = init.velocity;
            }
            break;
        case InitialState::Velocity::mode: {
            // Scaled so that the point at init.position moves at init.velocity.
            double largest = 0.0;
            for (Index i = 0; i < n; ++i) {
                if (is_v[static_cast<std::size_t>(i)]) largest = std::max(largest, std::abs(mode[i]));
            }
            const double at_point = shape.dot(mode);
            if (!(std::abs(at_point) > 1e-9 * largest)) {
                throw InputError("initial.velocity_mode: mode " + std::to_string(init.velocity_mode) +
                                 " has a nodal point at initial.position (it cannot be scaled to a velocity there)");
            }
            ic.v0 = mode * (init.velocity / at_point);
            break;
        }
    }
    return ic;
}

}  // namespace vi
