#include "dynamics/cvode/cvode_episodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vi::cvode_detail {

EpisodeRecorder::EpisodeRecorder(const ModalSystem& system, TransientResult& result) : sys_(system), r_(result) {
    const std::size_t nc = sys_.contacts().size();
    contact_of_.assign(static_cast<std::size_t>(sys_.elements()), -1);
    for (std::size_t j = 0; j < nc; ++j) contact_of_[static_cast<std::size_t>(sys_.contacts()[j])] = static_cast<int>(j);
    open_.assign(nc, -1);
    impulse_at_onset_.assign(nc, 0.0);
}

bool EpisodeRecorder::any_open() const {
    return std::any_of(open_.begin(), open_.end(), [](int k) { return k >= 0; });
}

void EpisodeRecorder::add_dissipation(double lo, double hi, const std::vector<int>& modes, const DenseOutput& at) {
    if (!(hi > lo) || !any_open()) return;
    // Two-point Gauss-Legendre on [-1, 1], exact for polynomials of degree 3: CVODE's steps are short
    // against the power's variation (its error control), so the rule's O(h^5) per step is far below
    // the solver's tolerance, at two evaluations of its interpolant per step.
    static const std::array<double, 2> node = {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
    static constexpr std::array<double, 2> weight = {1.0, 1.0};
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (std::size_t k = 0; k < node.size(); ++k) {
        const double t = mid + half * node[k];
        const double* y = at(t);
        for (std::size_t j = 0; j < open_.size(); ++j) {
            if (open_[j] < 0) continue;
            const int e = sys_.contacts()[j];
            const double p = sys_.dissipated_power(e, modes[static_cast<std::size_t>(e)], t, y);
            r_.episodes[static_cast<std::size_t>(open_[j])].contact_energy += half * weight[k] * p;
        }
    }
}

void EpisodeRecorder::on_switch(int e, int from, int to, double t, const double* y) {
    const int j = contact_of_[static_cast<std::size_t>(e)];
    if (j < 0) return;
    const std::size_t uj = static_cast<std::size_t>(j);
    const int contact = sys_.element(e).contact_mode();
    const ContactReading c = sys_.reading(e, t, y);
    // The stored energy the switch drops: what the run's ledger books as dissipated then.
    const double dropped = sys_.stored_energy(e, from, t, y) - sys_.stored_energy(e, to, t, y);
    if (to == contact && from != contact && open_[uj] < 0) {
        ContactEpisode ep;
        ep.support = j;
        ep.t_on = t;
        ep.v_in = c.point_velocity;
        ep.peak_force = std::max(c.force, 0.0);
        ep.peak_penetration = std::max(c.penetration, 0.0);
        ep.contact_energy = dropped;
        open_[uj] = static_cast<int>(r_.episodes.size());
        impulse_at_onset_[uj] = y[sys_.impulse_index(j)];
        r_.episodes.push_back(ep);
    } else if (to != contact && open_[uj] >= 0) {
        ContactEpisode& ep = r_.episodes[static_cast<std::size_t>(open_[uj])];
        ep.t_off = t;
        ep.v_out = c.point_velocity;
        ep.impulse = y[sys_.impulse_index(j)] - impulse_at_onset_[uj];
        ep.contact_energy += dropped;
        close(e, ep);
        open_[uj] = -1;
    }
}

void EpisodeRecorder::close(int e, ContactEpisode& ep) const {
    const ForceElement& el = sys_.element(e);
    ep.peak_pressure = el.contact_pressure(ep.peak_penetration);
    const double onset = el.yield_onset_pressure();
    if (!std::isnan(onset) && !std::isnan(ep.peak_pressure)) ep.yielded = ep.peak_pressure > onset;
}

void EpisodeRecorder::update_peaks(double t, const double* y) {
    for (std::size_t j = 0; j < open_.size(); ++j) {
        if (open_[j] < 0) continue;
        ContactEpisode& episode = r_.episodes[static_cast<std::size_t>(open_[j])];
        const ContactReading c = sys_.reading(sys_.contacts()[j], t, y);
        episode.peak_force = std::max(episode.peak_force, c.force);
        episode.peak_penetration = std::max(episode.peak_penetration, c.penetration);
    }
}

void EpisodeRecorder::update_extremes(double t, const double* y, const std::vector<int>& modes) {
    if (r_.episodes.empty()) return;
    Extremes& ex = r_.extremes;
    const double w = sys_.watched(y);
    if (!ex.valid) {
        ex.valid = true;
        ex.watched_max = ex.contact_max = -std::numeric_limits<double>::infinity();
        ex.watched_min = std::numeric_limits<double>::infinity();
    }
    if (w > ex.watched_max) {
        ex.watched_max = w;
        ex.watched_max_t = t;
    }
    bool in_contact = false;
    for (int e : sys_.contacts()) in_contact = in_contact || modes[static_cast<std::size_t>(e)] == sys_.element(e).contact_mode();
    if (in_contact && w < ex.watched_min) {
        ex.watched_min = w;
        ex.watched_min_t = t;
    }
    if (!sys_.contacts().empty()) ex.contact_max = std::max(ex.contact_max, sys_.contact_displacement(0, y));
}

void EpisodeRecorder::close_at_end(double t_end, const double* y) {
    for (std::size_t j = 0; j < open_.size(); ++j) {
        if (open_[j] < 0) continue;
        ContactEpisode& ep = r_.episodes[static_cast<std::size_t>(open_[j])];
        ep.t_off = t_end;
        ep.v_out = sys_.reading(sys_.contacts()[j], t_end, y).point_velocity;
        ep.impulse = y[sys_.impulse_index(static_cast<int>(j))] - impulse_at_onset_[j];
        ep.closed_at_end = true;
        close(sys_.contacts()[j], ep);
        open_[j] = -1;
    }
}

}  // namespace vi::cvode_detail
