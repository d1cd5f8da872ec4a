#include "dynamics/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "model/input_error.hpp"

namespace vi {
namespace {

using Index = Eigen::Index;

double penetration(const ContactElement& c, const Eigen::VectorXd& q) { return c.sign * (c.surface - q[c.dof]); }

// 2^k + 10 iterations for k contacts: every contact set once, and some slack (k capped against overflow).
int iteration_limit(std::size_t k) { return (1 << std::min<std::size_t>(k, 20)) + 10; }

// K with the springs of the closed contacts, and the load their surfaces put on the beam.
struct ClosedSystem {
    Eigen::LLT<Eigen::MatrixXd> llt;
    Eigen::VectorXd surface_load;
};

ClosedSystem closed_system(const Eigen::MatrixXd& K, const std::vector<ContactElement>& contacts,
                           const std::vector<bool>& active) {
    Eigen::MatrixXd Ka = K;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(K.rows());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        if (!active[k]) continue;
        const ContactElement& c = contacts[k];
        Ka(c.dof, c.dof) += c.stiffness;
        g[c.dof] += c.stiffness * c.surface;
    }
    ClosedSystem out{Eigen::LLT<Eigen::MatrixXd>(Ka), g};
    if (out.llt.info() != Eigen::Success) {
        throw std::runtime_error("static contact problem: the stiffness matrix is not positive definite");
    }
    return out;
}

// Tolerance on penetrations: a relative 1e-12 of the lengths in play, so that a surface that just
// touches (d = 0 up to round-off) counts as open.
double length_tolerance(const std::vector<ContactElement>& contacts, const Eigen::VectorXd& q, double extra) {
    double scale = std::abs(extra);
    for (const ContactElement& c : contacts) scale = std::max({scale, std::abs(c.surface), std::abs(q[c.dof])});
    return 1e-12 * scale;
}

// The contact set consistent with q: closed ones stay closed unless they would pull (d < -tol),
// open ones close when penetrated (d > tol).
std::vector<bool> updated_set(const std::vector<ContactElement>& contacts, const Eigen::VectorXd& q,
                              const std::vector<bool>& active, double tol) {
    std::vector<bool> next = active;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const double d = penetration(contacts[k], q);
        next[k] = active[k] ? d >= -tol : d > tol;
    }
    return next;
}

std::vector<bool> starting_set(const std::vector<ContactElement>& contacts, std::vector<bool> start) {
    if (start.size() == contacts.size()) return start;
    start.assign(contacts.size(), false);
    for (std::size_t k = 0; k < contacts.size(); ++k) start[k] = contacts[k].sign * contacts[k].surface > 0.0;
    return start;
}

std::string length_text(double v) {
    std::ostringstream s;
    s << v << " m";
    return s.str();
}

}  // namespace

StaticContactState solve_static_contact(const Eigen::MatrixXd& K, const std::vector<ContactElement>& contacts,
                                        const Eigen::VectorXd& f, std::vector<bool> start) {
    StaticContactState s;
    s.active = starting_set(contacts, std::move(start));
    for (int it = 0; it < iteration_limit(contacts.size()); ++it) {
        const ClosedSystem cs = closed_system(K, contacts, s.active);
        s.q = cs.llt.solve(f + cs.surface_load);
        std::vector<bool> next = updated_set(contacts, s.q, s.active, length_tolerance(contacts, s.q, 0.0));
        if (next == s.active) return s;
        s.active = std::move(next);
    }
    throw std::runtime_error("static contact problem did not converge");
}

PointStep solve_static_lift(const Eigen::MatrixXd& K, const std::vector<ContactElement>& contacts,
                            const Eigen::VectorXd& shape, double target, std::vector<bool> start) {
    PointStep p;
    p.state.active = starting_set(contacts, std::move(start));
    for (int it = 0; it < iteration_limit(contacts.size()); ++it) {
        const ClosedSystem cs = closed_system(K, contacts, p.state.active);
        const Eigen::VectorXd u = cs.llt.solve(shape);             // response to a unit point force
        const Eigen::VectorXd w = cs.llt.solve(cs.surface_load);   // response to the closed surfaces
        const double compliance = shape.dot(u);
        // A point so near a clamped or pinned end that its compliance underflows (x/l = 1e-300) is bad input.
        if (!(compliance > 0.0)) {
            throw InputError("initial.position: the point does not move under a static force (too close to a "
                             "clamped or pinned end)");
        }
        p.force = (target - shape.dot(w)) / compliance;
        p.state.q = p.force * u + w;
        std::vector<bool> next =
            updated_set(contacts, p.state.q, p.state.active, length_tolerance(contacts, p.state.q, target));
        if (next == p.state.active) return p;
        p.state.active = std::move(next);
    }
    throw std::runtime_error("static contact problem did not converge");
}

InitialConditions initial_conditions(const InitialState& init, const Eigen::MatrixXd& K,
                                     const std::vector<ContactElement>& contacts, const Eigen::VectorXd& shape,
                                     const std::vector<bool>& is_v, const Eigen::VectorXd& mode) {
    using Kind = InitialState::Kind;
    InitialConditions ic;
    ic.equilibrium = solve_static_contact(K, contacts, Eigen::VectorXd::Zero(K.rows()));
    const double v_eq = shape.dot(ic.equilibrium.q);
    switch (init.kind) {
        case Kind::rest:
            ic.stepped = ic.equilibrium;
            break;
        case Kind::displacement: {
            PointStep step = solve_static_lift(K, contacts, shape, v_eq + init.displacement, ic.equilibrium.active);
            ic.stepped = std::move(step.state);
            ic.force = step.force;
            break;
        }
        case Kind::force:
            ic.stepped = solve_static_contact(K, contacts, init.force * shape, ic.equilibrium.active);
            ic.force = init.force;
            break;
    }
    ic.lift = shape.dot(ic.stepped.q) - v_eq;

    // A support that closes during the step on the side the point moved towards: the static force
    // pressed the beam into it (e.g. a tip lifted past the gap of a support above). Supports already
    // closed at equilibrium (prestressed) and supports on the far side are part of a valid state.
    const char* key = init.kind == Kind::force ? "initial.force" : "initial.displacement";
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        if (!ic.stepped.active[k] || ic.equilibrium.active[k]) continue;
        if (contacts[k].sign * ic.lift >= 0.0) continue;
        throw InputError(std::string(key) + ": the initial state penetrates supports[" + std::to_string(k) +
                         "] (d = " + length_text(penetration(contacts[k], ic.stepped.q)) +
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
