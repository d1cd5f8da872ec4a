#include "problem/beam_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "forces/unilateral_contact.hpp"
#include "model/case_checks.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"
#include "problem/element_families.hpp"
#include "problem/film_elements.hpp"

// The model works on the bending DOFs (v, theta) only. In this linear beam model axial and bending
// decouple, supports and loads act transversely, so the axial DOFs are never loaded and stay at rest:
// leaving them out changes nothing but the size of the problem. Mid-plane stretching is the one
// coupling, and it enters as a force element whose axial force is uniform along the beam (the axial
// DOFs' equilibrium with the ends held, solved in closed form), so they stay out.

namespace vi {
namespace {

using Index = Eigen::Index;

// The lowest `count` unsupported bending modes; InputError on `key` when the model has fewer.
ModeSet bending_modes(const System& s, int count, const char* key) {
    ModeSet modes = lowest_modes(submatrix(s.K, s.bending), submatrix(s.M, s.bending), count);
    if (modes.omega.size() < count) {
        throw InputError(std::string(key) + ": mode " + std::to_string(count) + " does not exist (the model has " +
                         std::to_string(modes.omega.size()) + " bending modes; refine beam.elements)");
    }
    return modes;
}

// Ratios at two modes fix alpha and beta, but not every pair gives a stable model: a negative beta
// damps the high modes negatively (their ratio beta w / 2 falls without bound), and a negative alpha
// does so below some frequency, which must then lie under mode 1. Either is an InputError on
// damping.ratios; a value negative only by roundoff (ratios exactly on the boundary) counts as 0.
RayleighCoefficients rayleigh(const RayleighDamping& d, const ModeSet& modes) {
    if (!d.from_ratios) return {d.alpha, d.beta};
    const double w1 = modes.omega[d.mode1 - 1], w2 = modes.omega[d.mode2 - 1];
    RayleighCoefficients c = rayleigh_from_ratios(w1, d.ratio1, w2, d.ratio2);
    const double xi_max = std::max(d.ratio1, d.ratio2);
    const bool first_low = w1 < w2;
    const double w_lo = first_low ? w1 : w2, w_hi = first_low ? w2 : w1;
    const double xi_lo = first_low ? d.ratio1 : d.ratio2;
    const int m_lo = first_low ? d.mode1 : d.mode2, m_hi = first_low ? d.mode2 : d.mode1;
    if (c.beta < 0.0 && 0.5 * c.beta * w_hi >= -1e-12 * xi_max) c.beta = 0.0;
    if (c.beta < 0.0) {
        throw InputError("damping.ratios: they give beta = " + significant(c.beta, 3) +
                         " s < 0, which damps the high modes negatively (an unstable model); the ratio at mode " +
                         std::to_string(m_hi) + " must be at least " + significant(xi_lo, 3) + " x w" +
                         std::to_string(m_lo) + "/w" + std::to_string(m_hi) + " = " + significant(xi_lo * w_lo / w_hi, 3));
    }
    const double z1 = rayleigh_ratio(c, modes.omega[0]);
    if (z1 < -1e-12 * xi_max) {
        throw InputError("damping.ratios: they give mode 1 the damping ratio " + significant(z1, 3) +
                         " < 0 (alpha = " + significant(c.alpha, 3) + " 1/s; an unstable model)");
    }
    return c;
}

// Every registered family's elements, in the registry's order; each contact also under its name.
void add_elements(const Case& c, BeamModel& b) {
    const Eigen::VectorXd first_mode = b.modes.shapes.col(0);
    const ElementSource source{c, b.system, b.bending_position, first_mode};
    for (const ElementFamily* family : element_families()) {
        for (FamilyElement& made : family->elements(source)) {
            if (made.element->is_contact()) b.contacts.push_back({made.element->name(), b.forces.size(), made.entry});
            b.forces.push_back(std::move(made.element));
        }
    }
    // The supports' Kc and Cc (from a damping ratio where given), for reports, by support index; NaN
    // for a support whose law is not a linear spring-damper.
    b.contact_stiffness.assign(c.supports.size(), std::numeric_limits<double>::quiet_NaN());
    b.contact_damping.assign(c.supports.size(), std::numeric_limits<double>::quiet_NaN());
    for (const NamedContact& k : b.contacts) {
        if (k.entry.table != "supports") continue;
        const auto* support = dynamic_cast<const UnilateralContact*>(b.forces[k.element].get());
        if (support == nullptr) continue;
        b.contact_stiffness.at(k.entry.index) = support->stiffness();
        b.contact_damping.at(k.entry.index) = support->damping();
    }
}

// The watched DOF: v at the free end (the right end, else the left); when neither end is free, v at
// the node nearest initial.position (mid-span when that point is held by an end condition).
// The watched point's v among the bending DOFs; x_out is where it sits [m].
int watched_dof(const Case& c, const System& s, const std::vector<int>& pos, double& x_out) {
    const double l = s.length;
    double x = c.initial.position * l;
    if (c.beam.right == EndCondition::free) {
        x = l;
    } else if (c.beam.left == EndCondition::free) {
        x = 0.0;
    } else if (c.initial.position == 1.0 || !(c.initial.position > 0.0)) {
        x = 0.5 * l;
    }
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (int node = 0; node < s.mesh.node_count(); ++node) {
        const int r = s.reduced_of[static_cast<std::size_t>(global_dof(node, 1))];
        const double distance = std::abs(s.mesh.x[static_cast<std::size_t>(node)] - x);
        if (r >= 0 && distance < best_distance) {
            best = pos[static_cast<std::size_t>(r)];
            best_distance = distance;
            x_out = s.mesh.x[static_cast<std::size_t>(node)];
        }
    }
    return best;
}

// How many unsupported bending modes the case refers to (damping ratios, a modal initial velocity),
// and the key that asks for the highest.
std::pair<int, const char*> modes_asked(const Case& c) {
    int count = 1;
    const char* key = "initial.velocity_mode";
    if (c.damping.from_ratios) {
        count = std::max({count, c.damping.mode1, c.damping.mode2});
        key = "damping.modes";
    }
    if (c.initial.velocity_kind == InitialState::Velocity::mode && c.initial.velocity_mode > count) {
        count = c.initial.velocity_mode;
        key = "initial.velocity_mode";
    }
    return {count, key};
}

WatchedPoint watched_point(const Case& c, const System& s, const std::vector<int>& pos) {
    WatchedPoint w;
    double x = 0.0;
    w.dof = watched_dof(c, s, pos, x);
    w.x_over_l = x / s.length;
    const bool free_end = c.beam.right == EndCondition::free || c.beam.left == EndCondition::free;
    w.name = free_end ? "tip" : std::abs(w.x_over_l - 0.5) < 1e-9 ? "midspan" : "point";
    return w;
}

}  // namespace

const NamedContact* BeamModel::contact(const std::string& name) const {
    for (const NamedContact& k : contacts) {
        if (k.name == name) return &k;
    }
    return nullptr;
}

WatchedPoint watched_point_of(const Case& c) {
    const System s = build_system(c, SupportModel::none);
    return watched_point(c, s, bending_positions(s));
}

BeamModel build_beam_model(const Case& c) {
    if (const std::vector<CaseProblem> problems = check_case(c); !problems.empty()) {
        throw InputError(problems.front().key + ": " + problems.front().message);
    }
    BeamModel b;
    b.system = build_system(c, SupportModel::none);
    const System& s = b.system;
    b.bending_position = bending_positions(s);
    const std::vector<int>& pos = b.bending_position;
    b.is_v.resize(s.bending.size());
    for (std::size_t i = 0; i < s.bending.size(); ++i) b.is_v[i] = s.free_dofs[static_cast<std::size_t>(s.bending[i])] % 3 == 1;

    const auto [count, key] = modes_asked(c);
    b.modes = bending_modes(s, count, key);
    b.omega1 = b.modes.omega[0];
    b.rayleigh = rayleigh(c.damping, b.modes);
    b.films = film_regimes(c, b.omega1);
    b.M = submatrix(s.M, s.bending);
    b.K = submatrix(s.K, s.bending);
    add_elements(c, b);
    b.watched = watched_point(c, s, pos);
    return b;
}

}  // namespace vi
