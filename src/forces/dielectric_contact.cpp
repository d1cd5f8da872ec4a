#include "forces/dielectric_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vi {

DielectricContact::DielectricContact(std::string name, std::vector<int> dofs, std::vector<PadPoint> points,
                                     PadGeometry geometry, double line_stiffness)
    : name_(std::move(name)), dofs_(std::move(dofs)), points_(std::move(points)), geometry_(geometry),
      stiffness_(line_stiffness) {
    runs_ = point_runs(points_);
    if (points_.empty() || std::abs(geometry_.sign) != 1.0 || !(stiffness_ > 0.0) || !std::isfinite(stiffness_)) {
        throw std::invalid_argument(name_ + ": inconsistent dielectric contact data");
    }
}

DielectricContact::DielectricContact(std::string name, std::vector<int> dofs, std::vector<PadPoint> points,
                                     PadGeometry geometry, const AdhesiveLayerLaw& law)
    : DielectricContact(std::move(name), std::move(dofs), std::move(points), geometry, law.stiffness()) {
    law_ = law;
}

std::size_t DielectricContact::deepest(const double* q) const {
    std::size_t best = 0;
    double deepest_d = -std::numeric_limits<double>::infinity();
    for_each_penetration(q, [&](std::size_t k, double d) {
        if (d > deepest_d) {
            deepest_d = d;
            best = k;
        }
    });
    return best;
}

void DielectricContact::add_force(const ElementState& s, int mode, double* f) const {
    if (law_) {
        // The same law in both modes: it derives from one energy, with no memory of the contact.
        for (const PadPoint& p : points_) {
            const double q = law_->at(penetration(p, s.q)).force;
            if (q != 0.0) add_point_load(p, -geometry_.sign * q * p.weight, f);
        }
        return;
    }
    if (mode != 1) return;
    for (const PadPoint& p : points_) {
        const double d = penetration(p, s.q);
        if (d <= 0.0) continue;
        // The layer pushes the beam away from the electrode: -sign k d per unit length.
        add_point_load(p, -geometry_.sign * stiffness_ * d * p.weight, f);
    }
}

void DielectricContact::add_tangent(const ElementState& s, int mode, double* dfdq, double*) const {
    const std::size_t n = dofs_.size();
    if (law_) {
        for (const PadPoint& p : points_) {
            const double k = law_->at(penetration(p, s.q)).slope;
            if (k != 0.0) add_point_stiffness(p, -k * p.weight, n, dfdq);
        }
        return;
    }
    if (mode != 1) return;
    for (const PadPoint& p : points_) {
        if (penetration(p, s.q) <= 0.0) continue;
        // d f_i / d q_j = -sign k (d d / d q_j) N_i w = -k N_i N_j w (sign^2 = 1).
        add_point_stiffness(p, -stiffness_ * p.weight, n, dfdq);
    }
}

double DielectricContact::stored_energy(const ElementState& s, int mode) const {
    double e = 0.0;
    if (law_) {
        for (const PadPoint& p : points_) e += law_->at(penetration(p, s.q)).energy * p.weight;
        return e;
    }
    if (mode != 1) return 0.0;
    for (const PadPoint& p : points_) {
        const double d = penetration(p, s.q);
        if (d > 0.0) e += 0.5 * stiffness_ * d * d * p.weight;
    }
    return e;
}

double DielectricContact::switching_function(const ElementState& s, int mode) const {
    const double d = penetration(points_[deepest(s.q)], s.q);
    // Adhesive: closed until the last point leaves the attraction's range, so the episode ends where
    // the beam is free (not at each sub-nm vibration of a held beam about the face).
    if (law_ && mode == 1) return -(d + law_->range());
    return mode == 1 ? -d : d;
}

int DielectricContact::static_mode(const ElementState& s) const {
    const double d = penetration(points_[deepest(s.q)], s.q);
    return d > 1e-12 * geometry_.gap ? 1 : 0;
}

std::vector<std::vector<double>> DielectricContact::load_patterns() const {
    return line_load_patterns(points_, geometry_, dofs_.size());
}

ContactReading DielectricContact::contact_reading(const ElementState& s) const {
    ContactReading r;
    const PadPoint& p = points_[deepest(s.q)];
    r.penetration = penetration(p, s.q);
    r.force = contact_force(s);
    r.point_velocity = point_displacement(p, s.v);
    return r;
}

double DielectricContact::contact_force(const ElementState& s) const {
    double force = 0.0;
    for_each_penetration(s.q, [&](std::size_t k, double d) {
        const double w = points_[k].weight;
        if (law_) {
            force += law_->at(d).force * w;
        } else if (d > 0.0) {
            force += stiffness_ * d * w;
        }
    });
    return force;
}

double DielectricContact::contact_point_velocity(const ElementState& s) const {
    return point_displacement(points_[deepest(s.q)], s.v);
}

}  // namespace vi
