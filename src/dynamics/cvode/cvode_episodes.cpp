#include "dynamics/cvode/cvode_episodes.hpp"

#include <algorithm>
#include <limits>

namespace vi::cvode_detail {

EpisodeRecorder::EpisodeRecorder(const ModalSystem& system, TransientResult& result) : sys_(system), r_(result) {
    const std::size_t nc = sys_.contacts().size();
    contact_of_.assign(static_cast<std::size_t>(sys_.elements()), -1);
    for (std::size_t j = 0; j < nc; ++j) contact_of_[static_cast<std::size_t>(sys_.contacts()[j])] = static_cast<int>(j);
    open_.assign(nc, -1);
    impulse_at_onset_.assign(nc, 0.0);
}

void EpisodeRecorder::on_switch(int e, int from, int to, double t, const double* y) {
    const int j = contact_of_[static_cast<std::size_t>(e)];
    if (j < 0) return;
    const std::size_t uj = static_cast<std::size_t>(j);
    const int contact = sys_.element(e).contact_mode();
    const ContactReading c = sys_.reading(e, t, y);
    if (to == contact && from != contact && open_[uj] < 0) {
        ContactEpisode ep;
        ep.support = j;
        ep.t_on = t;
        ep.v_in = c.point_velocity;
        ep.peak_force = std::max(c.force, 0.0);
        ep.peak_penetration = std::max(c.penetration, 0.0);
        open_[uj] = static_cast<int>(r_.episodes.size());
        impulse_at_onset_[uj] = y[sys_.impulse_index(j)];
        r_.episodes.push_back(ep);
    } else if (to != contact && open_[uj] >= 0) {
        ContactEpisode& ep = r_.episodes[static_cast<std::size_t>(open_[uj])];
        ep.t_off = t;
        ep.v_out = c.point_velocity;
        ep.impulse = y[sys_.impulse_index(j)] - impulse_at_onset_[uj];
        open_[uj] = -1;
    }
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
    const double tip = sys_.tip(y);
    if (!ex.valid) {
        ex.valid = true;
        ex.tip_max = ex.contact_max = -std::numeric_limits<double>::infinity();
        ex.tip_min = std::numeric_limits<double>::infinity();
    }
    if (tip > ex.tip_max) {
        ex.tip_max = tip;
        ex.tip_max_t = t;
    }
    bool in_contact = false;
    for (int e : sys_.contacts()) in_contact = in_contact || modes[static_cast<std::size_t>(e)] == sys_.element(e).contact_mode();
    if (in_contact && tip < ex.tip_min) {
        ex.tip_min = tip;
        ex.tip_min_t = t;
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
        open_[j] = -1;
    }
}

}  // namespace vi::cvode_detail
