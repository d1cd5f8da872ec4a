// PieceSolution::sample_many: the history's samples of a piece a run at a time. After each anchor
// (or any sample), the samples that follow by the recurrence e_k <- e_k step_k are computed
// together: the recurrence mode by mode, the channels' sums over the modes for all samples of the
// run at once (vectorised across samples). Every value is formed by the same operations in the same
// order as sample() forms it, so the history is the same to the last bit.

#include <cmath>
#include <limits>
#include <vector>

#include "dynamics/exact/exact_state.hpp"
#include "dynamics/exact/modal_sums.hpp"

namespace vi {

namespace {
// Samples summed together at most: a run's exponentials and sums (about 40 live modes x 16 samples)
// stay in the first-level cache; the recurrence goes on across blocks, so the values do not change.
constexpr int kSampleBlock = 16;
}  // namespace

void PieceSolution::sample_many(const double* tau, const double* t_abs, int count, const std::vector<bool>& active,
                                TimeHistory& h) const {
    const std::size_t nc = p_->contacts.size();
    if (h.contact_v.size() != nc) {
        h.contact_v.resize(nc);
        h.contact_velocity.resize(nc);
        h.contact_force.resize(nc);
    }
    thread_local std::vector<const ExpSignal*> channels;
    thread_local std::vector<int> force_at;
    thread_local std::vector<double> er, ei, acc;  // grown only: every entry used is written first
    sampled_channels(active, channels, force_at);
    const int nf = static_cast<int>(channels.size());
    for (int i = 0; i < count;) {
        // Sample i as sample() takes it (an anchor or one step of the recurrence).
        static_cast<void>(sample_exponentials(tau[i], t_abs[i], false));  // kept in sample_e_
        pack_channels(channels);
        // The samples after it that sample() would take by the recurrence.
        int run = 0;
        for (int j = i + 1; j < count && sample_run_ + run < kSampleAnchor && run + 1 < kSampleBlock; ++j) {
            const double dt = tau[j] - tau[j - 1];
            if (!(dt > 0.0 && std::abs(dt - sample_dt_) <= 8.0 * std::numeric_limits<double>::epsilon() * t_abs[j])) break;
            ++run;
        }
        const int S = run + 1;
        const int nl = static_cast<int>(sample_live_.size());
        if (er.size() < static_cast<std::size_t>(nl * S)) {
            er.resize(static_cast<std::size_t>(nl * S));
            ei.resize(static_cast<std::size_t>(nl * S));
        }
        // Per live mode, its exponentials at the S samples: e, e step, (e step) step, ... as sample()
        // multiplies them (a complex product written out: re = ac - bd, im = ad + bc).
        for (int l = 0; l < nl; ++l) {
            const int k = sample_live_[static_cast<std::size_t>(l)];
            cd& e = sample_e_[k];
            const cd st = sample_step_.size() > k ? sample_step_[k] : cd(1.0, 0.0);
            double a = e.real(), b = e.imag();
            double* xr = er.data() + static_cast<std::ptrdiff_t>(l) * S;
            double* xi = ei.data() + static_cast<std::ptrdiff_t>(l) * S;
            xr[0] = a;
            xi[0] = b;
            for (int s = 1; s < S; ++s) {
                const double c = st.real(), d = st.imag();
                const double re = a * c - b * d, im = a * d + b * c;
                a = re;
                b = im;
                xr[s] = a;
                xi[s] = b;
            }
            e = cd(a, b);
        }
        sample_run_ += run;
        sample_tau_ = tau[i + run];
        if (acc.size() < static_cast<std::size_t>(nf * S)) acc.resize(static_cast<std::size_t>(nf * S));
        add_channel_runs(sample_pack_.data(), nf, sample_live_.data(), nl, er.data(), ei.data(), S, acc.data());
        for (int s = 0; s < S; ++s) {
            auto value = [&](int j) {
                double v = acc[static_cast<std::size_t>(j * S + s)];
                for (const ExpTerm& t : channels[static_cast<std::size_t>(j)]->terms) v += term_derivative(t, tau[i + s], 0).real();
                return v;
            };
            record_sample(h, t_abs[i + s], force_at, value);
        }
        i += S;
    }
}

}  // namespace vi
