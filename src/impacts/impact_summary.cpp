#include "impacts/impact_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vi {
namespace {

std::vector<Impact> group_episodes(const std::vector<ContactEpisode>& episodes, double gap) {
    std::vector<Impact> impacts;
    std::vector<int> last_of_support;  // index into impacts of each support's current impact
    for (const ContactEpisode& e : episodes) {
        if (static_cast<int>(last_of_support.size()) <= e.support) last_of_support.resize(e.support + 1, -1);
        const int li = last_of_support[static_cast<std::size_t>(e.support)];
        if (li >= 0 && e.t_on - impacts[static_cast<std::size_t>(li)].t_off < gap) {
            Impact& im = impacts[static_cast<std::size_t>(li)];
            im.t_off = e.t_off;
            im.v_out = e.v_out;
            // fmax: an episode whose peaks were not computed (NaN, TransientOptions::peak_level) adds none.
            im.peak_force = std::fmax(im.peak_force, e.peak_force);
            im.peak_penetration = std::fmax(im.peak_penetration, e.peak_penetration);
            im.impulse += e.impulse;
            im.closed_at_end = e.closed_at_end;
            im.contact_energy += e.contact_energy;
            im.peak_pressure = std::isnan(e.peak_pressure) ? e.peak_pressure : std::max(im.peak_pressure, e.peak_pressure);
            if (e.yielded) im.yielded = im.yielded.value_or(false) || *e.yielded;
            ++im.episodes;
            continue;
        }
        Impact im;
        im.support = e.support;
        im.t_on = e.t_on;
        im.t_off = e.t_off;
        im.v_in = e.v_in;
        im.v_out = e.v_out;
        im.peak_force = e.peak_force;
        im.peak_penetration = e.peak_penetration;
        im.impulse = e.impulse;
        im.episodes = 1;
        im.closed_at_end = e.closed_at_end;
        im.contact_energy = e.contact_energy;
        im.peak_pressure = e.peak_pressure;
        im.yielded = e.yielded;
        last_of_support[static_cast<std::size_t>(e.support)] = static_cast<int>(impacts.size());
        impacts.push_back(im);
    }
    std::sort(impacts.begin(), impacts.end(), [](const Impact& a, const Impact& b) { return a.t_on < b.t_on; });
    return impacts;
}

}  // namespace

double grouping_gap(const ImpactSettings& s) {
    return !s.group ? 0.0 : s.group_gap > 0.0 ? s.group_gap : 0.25 * 2.0 * std::numbers::pi / s.omega1;
}

ContactDamage contact_damage(const std::vector<Impact>& impacts) {
    ContactDamage d;
    d.peak_pressure = std::numeric_limits<double>::quiet_NaN();
    for (const Impact& im : impacts) {
        d.contact_energy += im.contact_energy;
        d.peak_force = std::fmax(d.peak_force, im.peak_force);
        if (!std::isnan(im.peak_pressure)) {
            d.peak_pressure = std::isnan(d.peak_pressure) ? im.peak_pressure : std::max(d.peak_pressure, im.peak_pressure);
        }
        if (im.yielded) {
            d.yield_known = true;
            d.yield_impacts += *im.yielded ? 1 : 0;
        }
    }
    return d;
}

ImpactSummary summarize_impacts(const TransientResult& r, const ImpactSettings& s) {
    ImpactSummary out;
    out.group_gap = grouping_gap(s);
    out.impacts = group_episodes(r.episodes, out.group_gap);
    // A run that an element ended (the beam collapsing onto an electrode) never settles: T_p has no
    // value, and its reason is that outcome.
    const std::string ended = r.ended_by ? r.ended_by->reading.outcome : std::string();
    if (out.impacts.empty()) {
        out.Tp_reason = ended.empty() ? "no_impact" : ended;
        return out;
    }
    out.cycle_support = out.impacts.front().support;
    std::vector<const Impact*> own;
    for (const Impact& im : out.impacts) {
        if (im.support == out.cycle_support) own.push_back(&im);
    }
    for (std::size_t i = 0; i + 1 < own.size(); ++i) {
        out.T.push_back(own[i + 1]->t_on - own[i]->t_on);
        out.T1.push_back(own[i + 1]->t_on - own[i]->t_off);
    }
    for (const Impact* im : own) {
        if (!im->closed_at_end) out.T2.push_back(im->t_off - im->t_on);
    }
    if (!out.T.empty()) out.T_first = out.T.front();
    if (!out.T1.empty()) out.T1_first = out.T1.front();
    if (!out.T2.empty()) out.T2_first = out.T2.front();

    // T_p: end of the last impact still above the settle threshold: its peak penetration against a
    // fraction of the first impact's, or its approach speed against settle_velocity.
    const double threshold = s.settle_tolerance * out.impacts.front().peak_penetration;
    const auto big = [&](const Impact& im) {
        return s.settle_by_velocity ? std::abs(im.v_in) >= s.settle_velocity : im.peak_penetration > threshold;
    };
    const Impact* last_big = nullptr;
    for (const Impact& im : out.impacts) {
        if (big(im)) last_big = &im;
    }
    const Impact& final_impact = out.impacts.back();
    // A bounce lasts a fraction of a period; contact held for a whole first period is lasting.
    const double period1 = 2.0 * std::numbers::pi / s.omega1;
    const bool lasting = final_impact.closed_at_end && final_impact.t_off - final_impact.t_on > period1;
    if (last_big == nullptr) {
        // Only with the velocity rule: no impact came in at settle_velocity, so the process was
        // settled from the first contact on.
        out.Tp = out.impacts.front().t_on;
        out.Tp_reason = "below_threshold";
    } else if (lasting) {
        // Contact never lost again (prestress, or a beam come to rest on its support): T_p is the
        // onset of that lasting contact, provided the bouncing before it had settled.
        out.Tp = final_impact.t_on;
        out.Tp_reason = "persistent_contact";
    } else if (last_big != &final_impact) {
        // A smaller impact followed the last big one: the decay has been seen.
        out.Tp = last_big->t_off;
        out.Tp_reason = "settled";
    } else {
        out.Tp_reason = "horizon";
    }
    if (!ended.empty()) {
        out.Tp.reset();
        out.Tp_reason = ended;
    }
    if (r.extremes.valid) {
        out.y_max = r.extremes.watched_max - s.tip_equilibrium;
        out.z_max = *out.y_max / s.length;
        out.y_max_contact = r.extremes.contact_max - s.contact_equilibrium;
        out.watched_min = r.extremes.watched_min;
    }
    return out;
}

}  // namespace vi
