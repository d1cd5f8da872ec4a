#include "impacts/switching_ledger.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "model/number_format.hpp"

namespace vi {
namespace {

std::string us_text(double t) { return significant(t * 1e6, 4) + " us"; }

// Where g, linear from (t0, a) to (t1, b), reaches the level `level` (a and b on either side of it).
double crossing(double t0, double a, double t1, double b, double level) {
    return t0 + (t1 - t0) * (level - a) / (b - a);
}

// The first time |g| rises above `thr` on [0, period) of a sine, scanned in 1/512 of the period and
// refined by bisection (bounded loops); |g| is certain to pass thr within one period.
double harmonic_on(const TimeFunction& g, double thr) {
    if (std::abs(g(0.0)) > thr) return 0.0;
    const double period = 1.0 / g.frequency_hz;
    constexpr int kScan = 512;
    for (int i = 1; i <= kScan; ++i) {
        double lo = period * (i - 1) / kScan, hi = period * i / kScan;
        if (std::abs(g(hi)) <= thr) continue;
        for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (lo + hi);
            (std::abs(g(mid)) > thr ? hi : lo) = mid;
        }
        return hi;
    }
    return 0.0;  // unreachable for a sine whose largest |g| exceeds thr
}

// One electrode's window, thr = the off level of |g| (g dimensionless, V = voltage g).
VoltageWindow window_of(const TimeFunction& g, double thr) {
    VoltageWindow w;
    switch (g.kind) {
        case TimeFunction::Kind::constant: w.on = 0.0; return w;
        case TimeFunction::Kind::step: w.on = g.t_on; return w;
        case TimeFunction::Kind::harmonic: w.on = harmonic_on(g, thr); return w;
        case TimeFunction::Kind::table: break;
    }
    const std::vector<double>& t = g.times;
    const std::vector<double>& v = g.values;
    // Held before the first knot and after the last; linear between, so |g| can pass thr only once
    // per segment whose ends lie on either side of it.
    if (std::abs(v.front()) > thr) {
        w.on = 0.0;
    } else {
        for (std::size_t i = 0; i + 1 < v.size(); ++i) {
            if (std::abs(v[i + 1]) > thr) {
                w.on = crossing(t[i], v[i], t[i + 1], v[i + 1], std::copysign(thr, v[i + 1]));
                break;
            }
        }
    }
    if (std::abs(v.back()) > thr) return w;
    for (std::size_t i = v.size() - 1; i-- > 0;) {
        if (std::abs(v[i]) > thr) {
            w.off = crossing(t[i], v[i], t[i + 1], v[i + 1], std::copysign(thr, v[i]));
            break;
        }
    }
    return w;
}

}  // namespace

VoltageWindow voltage_window(const std::vector<Electrode>& electrodes) {
    VoltageWindow all;
    bool never_off = false;
    for (const Electrode& e : electrodes) {
        const double peak = std::abs(e.voltage) * e.time.max_abs();
        if (!(peak > 0.0)) continue;
        const VoltageWindow w = window_of(e.time, kVoltageOffFraction * e.time.max_abs());
        if (w.on) all.on = all.on ? std::min(*all.on, *w.on) : *w.on;
        if (!w.off) never_off = true;
        if (w.off) all.off = all.off ? std::max(*all.off, *w.off) : *w.off;
    }
    if (never_off || !all.on) all.off.reset();
    return all;
}

namespace {

std::string newton_text(double f) { return significant(f, 4) + " N"; }

// A layer's force over the last period of mode 1 before the horizon (from `from` on, if later) [N]:
// a beam held down still vibrates, and its layer's force swings about the holding force with it.
double mean_force(const TimeHistory& h, const std::vector<double>& f, double from, double to) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < f.size() && i < h.t.size(); ++i) {
        if (h.t[i] < from || h.t[i] > to) continue;
        sum += f[i];
        ++n;
    }
    return n > 0 ? sum / n : f.back();
}

// The first adhesive contact closed at the horizon that pulls (its force negative; a layer's on
// average over the last period, from `settled` on): adhesion holds it.
std::optional<StuckBalance> stuck_balance(const TransientResult& r, const std::vector<LedgerContact>& contacts,
                                          double settled) {
    for (const ContactEpisode& e : r.episodes) {
        const auto j = static_cast<std::size_t>(e.support);
        if (j >= contacts.size()) continue;
        const LedgerContact& k = contacts[j];
        if (!e.closed_at_end || !(k.hold || k.layer) || j >= r.history.contact_force.size()) continue;
        const std::vector<double>& f = r.history.contact_force[j];
        if (f.empty()) continue;
        if (k.layer) {
            const double mean = mean_force(r.history, f, settled, r.t_end);
            if (!(mean < 0.0)) continue;
            return StuckBalance{e.support, k.name, k.layer->restoring_force, k.layer->even_pull_off_force, mean, k.layer};
        }
        if (!(f.back() < 0.0)) continue;
        return StuckBalance{e.support, k.name, k.hold->restoring_force, k.hold->pull_off_force, f.back(), std::nullopt};
    }
    return std::nullopt;
}

std::string number_text(double v, const char* unit) { return significant(v, 4) + " " + unit; }

// The peel balance of a layer that holds the beam (docs/adhesion.md §10).
std::string layer_reason(const StuckBalance& b, double held_for) {
    const LayerHold& h = *b.layer;
    std::string why = b.contact;
    why.append(" still holds ").append(us_text(held_for)).append(" after the voltage fell: ");
    const double released = std::max(h.release_from, h.release_to);
    why.append("held flat on its layer, the beam would release at most ");
    why.append(std::isfinite(released) ? number_text(released, "J/m") : std::string("unbounded strain energy"));
    why.append(" per unit length peeled at the span's edges, against the adhesion energy w w_e = ");
    why.append(number_text(h.adhesion_energy, "J/m"));
    if (h.sticks) {
        char span[96];
        std::snprintf(span, sizeof span, "x = %.4g to %.4g um", h.contact_from * 1e6, h.contact_to * 1e6);
        why.append(released > h.adhesion_energy ? ", so it peels back and stays down over " : ", so it stays down over ");
        why.append(span).append(" (the static balance sticks above w = ");
        why.append(number_text(h.critical_work_of_adhesion, "J/m^2")).append("); its restoring force there is ");
        why.append(newton_text(b.restoring_force)).append(", against the ").append(newton_text(b.pull_off_force));
        why.append(" that contact would hold if lifted evenly");
    } else {
        why.append(", so by the static balance it peels off entirely (it sticks only above w = ");
        why.append(number_text(h.critical_work_of_adhesion, "J/m^2")).append(")");
    }
    why.append("; the layer pulls with ").append(newton_text(-b.contact_force)).append(" on average over the last period");
    return why;
}

}  // namespace

namespace {

// The collapse that ended r, if an electrode's terminal mode did.
std::optional<SwitchingCollapse> collapse_of(const TransientResult& r, const std::vector<Electrode>& electrodes) {
    if (!r.ended_by || r.ended_by->reading.outcome != "collapsed") return std::nullopt;
    SwitchingCollapse c{r.ended_by->name, r.ended_by->t, r.ended_by->reading.x, 0.0, r.ended_by->reading.value};
    for (std::size_t k = 0; k < electrodes.size(); ++k) {
        if (c.electrode == "electrodes[" + std::to_string(k) + "]") c.voltage = electrodes[k].voltage * electrodes[k].time(c.time);
    }
    return c;
}

// The bounces among L.contacts (a prefix of r.episodes) followed by a flight of at least gap before
// the next episode, or by none.
int grouped_bounce_count(const SwitchingLedger& L, const std::vector<ContactEpisode>& eps, double gap) {
    int n = 0;
    for (std::size_t i = 0; i < L.contacts.size(); ++i) {
        const ContactEpisode& e = eps[i];
        const bool bounce = !e.closed_at_end && !(L.stable_contact && e.t_on >= *L.stable_contact);
        if (bounce && (i + 1 >= eps.size() || eps[i + 1].t_on - e.t_off >= gap)) ++n;
    }
    return n;
}

}  // namespace

std::string bounce_text(const SwitchingLedger& l) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%d (every separation, chatter included); %d after a flight of at least %.4g us", l.bounces,
                  l.grouped_bounces, l.group_gap * 1e6);
    return buf;
}

SwitchingLedger switching_ledger(const TransientResult& r, const std::vector<Electrode>& electrodes, double omega1,
                                 const std::vector<LedgerContact>& contacts, double group_gap) {
    SwitchingLedger L = switching_ledger_to_end(r, electrodes, omega1, contacts);
    L.group_gap = group_gap > 0.0 ? group_gap : 0.25 * 2.0 * std::numbers::pi / omega1;
    L.collapse = collapse_of(r, electrodes);
    if (!L.collapse) {
        L.grouped_bounces = grouped_bounce_count(L, r.episodes, L.group_gap);
        return L;
    }
    // The run ended at the collapse: no contact after it, none stable, nothing released.
    L.state = "collapsed";
    L.reason = r.ended_by->reading.text;
    L.stable_contact.reset();
    L.release_time.reset();
    L.stuck.reset();
    L.bounces = 0;
    L.contacts.clear();
    L.peak_force = 0.0;
    for (const ContactEpisode& e : r.episodes) {
        L.contacts.push_back({e.support, e.t_on, e.t_off, e.v_in, e.peak_force, e.closed_at_end});
        L.peak_force = std::max(L.peak_force, e.peak_force);
        if (!e.closed_at_end) ++L.bounces;
    }
    L.grouped_bounces = grouped_bounce_count(L, r.episodes, L.group_gap);
    return L;
}

SwitchingLedger switching_ledger_to_end(const TransientResult& r, const std::vector<Electrode>& electrodes, double omega1,
                                        const std::vector<LedgerContact>& contacts) {
    SwitchingLedger L;
    L.voltage = voltage_window(electrodes);
    const std::vector<ContactEpisode>& eps = r.episodes;
    const double horizon = r.t_end;
    if (eps.empty()) {
        L.state = "never_closed";
        L.reason = !L.voltage.on ? "no electrode has a voltage"
                                 : "no support closed in the horizon (" + us_text(horizon) + ")";
        return L;
    }
    L.closing_time = eps.front().t_on;
    const bool fell = L.voltage.off && *L.voltage.off < horizon;
    // Stable: closed when the voltage falls; or, with the voltage still on, closed to the horizon for
    // at least one period of mode 1 (a younger contact may still bounce open).
    const double period = 2.0 * std::numbers::pi / omega1;
    std::optional<std::size_t> stable;
    bool young = false;
    for (std::size_t i = 0; i < eps.size(); ++i) {
        const ContactEpisode& e = eps[i];
        const bool held = fell ? (e.t_on < *L.voltage.off && (e.closed_at_end || e.t_off >= *L.voltage.off))
                               : e.closed_at_end;
        if (!held) continue;
        if (!fell && horizon - e.t_on < period) {
            young = true;
            continue;
        }
        stable = i;
        break;
    }
    for (std::size_t i = 0; i < eps.size(); ++i) {
        const ContactEpisode& e = eps[i];
        if (stable ? i > *stable : (fell && e.t_on >= *L.voltage.off)) break;
        L.contacts.push_back({e.support, e.t_on, e.t_off, e.v_in, e.peak_force, e.closed_at_end});
        L.peak_force = std::max(L.peak_force, e.peak_force);
        if (!e.closed_at_end && (!stable || i < *stable)) ++L.bounces;
    }
    if (stable) L.stable_contact = eps[*stable].t_on;

    const bool closed_at_end = std::any_of(eps.begin(), eps.end(), [](const ContactEpisode& e) { return e.closed_at_end; });
    double last_end = 0.0;
    for (const ContactEpisode& e : eps) last_end = std::max(last_end, e.t_off);
    if (closed_at_end) {
        L.state = "closed";
        if (fell) {
            L.reason = "the horizon ended " + us_text(horizon - *L.voltage.off) + " after the voltage fell";
            L.stuck = stuck_balance(r, contacts, std::max(*L.voltage.off, horizon - period));
            if (L.stuck && L.stuck->layer) {
                L.state = "stuck";
                L.reason = layer_reason(*L.stuck, horizon - *L.voltage.off);
            } else if (L.stuck) {
                const StuckBalance& b = *L.stuck;
                L.state = "stuck";
                std::string why = b.contact;
                why.append(" still holds ").append(us_text(horizon - *L.voltage.off));
                why.append(" after the voltage fell: the beam's elastic restoring force there, ");
                why.append(newton_text(b.restoring_force)).append(", is ");
                why.append(b.restoring_force < b.pull_off_force ? "below" : "above").append(" the pull-off force ");
                why.append(newton_text(b.pull_off_force)).append("; the contact pulls with ");
                why.append(newton_text(-b.contact_force)).append(" at the horizon");
                L.reason = why;
            }
        } else if (L.voltage.off) {
            L.reason = "the voltage falls at " + us_text(*L.voltage.off) + ", after the horizon";
        } else {
            L.reason = "the voltage never falls";
        }
        if (!stable && young) {
            L.reason += "; the last contact began less than one period of mode 1 (" + us_text(period) +
                        ") before the horizon ended, too late to call it stable";
        }
    } else if (!fell) {
        L.state = "bouncing";
        L.reason = "open at the horizon with the voltage on; the last contact ended at " + us_text(last_end);
    } else if (last_end >= *L.voltage.off) {
        L.state = "released";
        L.release_time = last_end;
        L.reason = "the last contact ended " + us_text(last_end - *L.voltage.off) +
                   " after the voltage fell and the switch stayed open to the horizon";
    } else {
        L.state = "opened_before_voltage_off";
        L.reason = "the last contact ended at " + us_text(last_end) + ", before the voltage fell at " +
                   us_text(*L.voltage.off);
    }
    return L;
}

}  // namespace vi
