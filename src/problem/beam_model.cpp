#include "problem/beam_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "forces/adhesive_contact.hpp"
#include "forces/kelvin_voigt_contact.hpp"
#include "forces/midplane_stretching.hpp"
#include "forces/point_load_element.hpp"
#include "model/case_checks.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"
#include "problem/electrode_elements.hpp"
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

// One Kelvin-Voigt contact element per support, on the v DOF of its node. Surfaces in beam
// coordinates (v up): below, +Support::surface (a prestress lifts it above the unloaded axis); above,
// -Support::surface. Cc from a damping ratio zeta: Cc = 2 zeta sqrt(Kc m_eff), with m_eff = 1 /
// phi1(x0)^2 the effective mass of the first unsupported bending mode (mass normalised) at the
// support: the critical damping of that mode's one-DOF model on the support spring.
void add_contacts(const Case& c, const System& s, const std::vector<int>& pos, const Eigen::VectorXd& phi1,
                  BeamModel& b) {
    for (std::size_t k = 0; k < c.supports.size(); ++k) {
        const Support& sup = c.supports[k];
        const std::string name = "supports[" + std::to_string(k) + "]";
        const int r = s.support_dof[k];
        if (r < 0) {
            throw InputError(name + ".position: the support sits on a node held by an end condition (v never moves there)");
        }
        const int dof = pos[static_cast<std::size_t>(r)];
        double damping = sup.damping;
        if (sup.damping_ratio) {
            const double phi = phi1[dof];
            if (!(std::abs(phi) > 1e-9 * phi1.cwiseAbs().maxCoeff())) {
                throw InputError(name + ".damping_ratio: the first mode does not move at the support (give damping)");
            }
            damping = 2.0 * *sup.damping_ratio * std::sqrt(sup.stiffness) / std::abs(phi);
        }
        const double sign = sup.side == Side::below ? 1.0 : -1.0;
        const double surface = sup.side == Side::below ? sup.surface : -sup.surface;
        const double x = s.mesh.x[static_cast<std::size_t>(s.mesh.support_nodes[k])];
        if (sup.adhesion == Adhesion::none) {
            b.forces.push_back(std::make_shared<KelvinVoigtContact>(name, dof, sign, surface, sup.stiffness, damping, x));
        } else {
            // One element, not a second one beside the contact: adhesion changes when the contact opens,
            // and an element's mode is its own (docs/adhesion.md §3).
            b.forces.push_back(std::make_shared<AdhesiveContact>(
                name, dof, sign, surface, sup.stiffness, damping, x, sup.pull_off_force(), sup.adhesion_range,
                sup.adhesion == Adhesion::dmt ? "DMT" : "JKR"));
        }
        b.contacts.push_back({name, b.forces.size() - 1});
        b.contact_stiffness.push_back(sup.stiffness);
        b.contact_damping.push_back(damping);
    }
}

// One point-load element per load: its consistent load vector's nonzero entries.
void add_loads(const Case& c, const System& s, BeamModel& b) {
    for (std::size_t k = 0; k < c.loads.size(); ++k) {
        const PointLoad& load = c.loads[k];
        const Eigen::VectorXd shape = unit_point_load(s, load.position);
        std::vector<int> dofs;
        std::vector<double> weights;
        for (Index i = 0; i < shape.size(); ++i) {
            if (shape[i] == 0.0) continue;
            dofs.push_back(static_cast<int>(i));
            weights.push_back(shape[i]);
        }
        b.forces.push_back(std::make_shared<PointLoadElement>("loads[" + std::to_string(k) + "]", std::move(dofs),
                                                                   std::move(weights), load.amplitude, load.time,
                                                                   load.position * s.length));
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

std::vector<int> bending_positions(const System& s) {
    std::vector<int> pos(static_cast<std::size_t>(s.size()), -1);
    for (std::size_t i = 0; i < s.bending.size(); ++i) pos[static_cast<std::size_t>(s.bending[i])] = static_cast<int>(i);
    return pos;
}

Eigen::VectorXd on_bending(const System& s, const Eigen::VectorXd& reduced) {
    Eigen::VectorXd out(static_cast<Index>(s.bending.size()));
    for (std::size_t i = 0; i < s.bending.size(); ++i) out[static_cast<Index>(i)] = reduced[s.bending[i]];
    return out;
}

Eigen::VectorXd unit_point_load(const System& s, double position) {
    return on_bending(s, transverse_point_load(s, position * s.length, 1.0));
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
    add_contacts(c, s, pos, b.modes.shapes.col(0), b);
    add_loads(c, s, b);
    for (auto& pad : electrode_elements(c, s, pos, false)) b.forces.push_back(std::move(pad));
    for (auto& layer : dielectric_contacts(c, s, pos)) {
        b.contacts.push_back({layer->name(), b.forces.size()});
        b.forces.push_back(std::move(layer));
    }
    // The gas films damp only: they leave the static state alone (no force at v = 0).
    for (auto& film : film_elements(c, s, pos)) b.forces.push_back(std::move(film));
    if (c.beam.stretching) {
        // The axis's lengthening, on every bending DOF; E is the modulus bending uses.
        b.forces.push_back(std::make_shared<MidplaneStretching>("beam.stretching", submatrix(s.G, s.bending),
                                                                s.props.E * s.props.A / s.length));
    }
    b.watched = watched_point(c, s, pos);
    return b;
}

}  // namespace vi
