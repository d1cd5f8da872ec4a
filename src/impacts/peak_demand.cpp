#include "impacts/peak_demand.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace vi {
namespace {

// Incremental grouping of episodes into impacts, as summarize_impacts groups them: an episode joins
// its support's last impact when it begins less than the gap after that impact's last episode ended.
class LeadingImpactsLevel {
public:
    LeadingImpactsLevel(const ImpactSettings& s, int leading)
        : gap_(grouping_gap(s)), tolerance_(s.settle_tolerance), by_velocity_(s.settle_by_velocity),
          leading_(std::max(leading, 1)) {}

    double operator()(const std::vector<ContactEpisode>& episodes) {
        if (episodes.empty()) return -std::numeric_limits<double>::infinity();
        if (episodes.size() != seen_ + 1) restart();
        while (seen_ < episodes.size()) add(episodes, seen_++);
        const auto impact = static_cast<std::size_t>(impact_of_.back());
        const auto last_leading = static_cast<std::size_t>(leading_ - 1);
        // Impacts of equal onset may come in either order from the summary's sort: a tie with the
        // last leading impact is read as a leading one.
        if (impact <= last_leading || onset_[impact] == onset_[last_leading]) return -std::numeric_limits<double>::infinity();
        if (by_velocity_) return std::numeric_limits<double>::infinity();
        // The summary's first impact is one of those that begin with impact 0: the smallest of their peaks.
        // Only once those impacts can grow no more is the threshold known: before, every peak in full.
        double first_peak = std::numeric_limits<double>::infinity();
        for (const FirstImpact& f : first_) {
            if (!f.ended) return -std::numeric_limits<double>::infinity();
            first_peak = std::min(first_peak, std::fmax(f.closed_peak, episodes[f.latest].peak_penetration));
        }
        return tolerance_ * first_peak;
    }

private:
    void restart() {
        seen_ = 0;
        impacts_ = 0;
        impact_of_.clear();
        last_episode_of_support_.clear();
        onset_.clear();
        first_.clear();
    }

    void add(const std::vector<ContactEpisode>& episodes, std::size_t e) {
        const ContactEpisode& ep = episodes[e];
        const auto support = static_cast<std::size_t>(ep.support);
        if (last_episode_of_support_.size() <= support) last_episode_of_support_.resize(support + 1, -1);
        const long last = last_episode_of_support_[support];
        int impact = impacts_;
        if (last >= 0 && ep.t_on - episodes[static_cast<std::size_t>(last)].t_off < gap_) {
            impact = impact_of_[static_cast<std::size_t>(last)];
        } else {
            ++impacts_;
            onset_.push_back(ep.t_on);
            // Its support's previous impact, if one of the first, can take no further episode.
            for (FirstImpact& f : first_) f.ended = f.ended || f.support == ep.support;
        }
        impact_of_.push_back(impact);
        last_episode_of_support_[support] = static_cast<long>(e);
        const auto k = static_cast<std::size_t>(impact);
        if (onset_[k] != onset_[0]) return;
        // The impact's episodes before this one have ended (one support closes one at a time).
        if (k < first_.size()) {
            first_[k].closed_peak = std::fmax(first_[k].closed_peak, episodes[first_[k].latest].peak_penetration);
            first_[k].latest = e;
        } else {
            first_.push_back({0.0, e, ep.support, false});
        }
    }

    double gap_, tolerance_;
    bool by_velocity_;
    int leading_;
    std::size_t seen_ = 0;
    int impacts_ = 0;
    std::vector<int> impact_of_;
    std::vector<long> last_episode_of_support_;
    std::vector<double> onset_;  // of each impact
    // The impacts that begin with the first (the summary's first impact is one of them): the peak
    // penetration of their ended episodes, their latest episode (its peak may still grow), their
    // support, and whether it has begun another impact since (then the impact has ended for good).
    struct FirstImpact {
        double closed_peak;
        std::size_t latest;
        int support;
        bool ended;
    };
    std::vector<FirstImpact> first_;
};

}  // namespace

std::function<double(const std::vector<ContactEpisode>&)> leading_impacts_peak_level(const ImpactSettings& s, int leading) {
    return LeadingImpactsLevel(s, leading);
}

}  // namespace vi
