#include "study/cycles/cycles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "impacts/simulation.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// g on [0, P) repeated n times: the table's knots shifted by k P. Between the last knot of one copy
// and the first of the next, g is straight (as a table is between any two knots).
TimeFunction repeated_table(const TimeFunction& g, double period, int n, const std::string& key) {
    if (g.times.empty() || g.times.front() < 0.0 || !(g.times.back() < period)) {
        throw InputError(key + ": the drive must lie within one period to repeat it: its knots run from " +
                         significant(g.times.empty() ? 0.0 : g.times.front(), 6) + " s to " +
                         significant(g.times.empty() ? 0.0 : g.times.back(), 6) + " s, the period is " +
                         significant(period, 6) + " s (--period)");
    }
    TimeFunction r;
    r.kind = TimeFunction::Kind::table;
    r.times.reserve(g.times.size() * static_cast<std::size_t>(n));
    r.values.reserve(r.times.capacity());
    for (int k = 0; k < n; ++k) {
        for (std::size_t i = 0; i < g.times.size(); ++i) {
            r.times.push_back(g.times[i] + k * period);
            r.values.push_back(g.values[i]);
        }
    }
    return r;
}

// The intervals (contact episodes, conduction stretches) that begin in [t0, t1), times from t0, cut
// at t1; one cut there is still open at its end (`open_at_end`, the interval type's own flag).
template <class Interval>
std::vector<Interval> slice(const std::vector<Interval>& all, double t0, double t1, bool Interval::*open_at_end) {
    std::vector<Interval> out;
    for (const Interval& e : all) {
        if (e.t_on < t0 || e.t_on >= t1) continue;
        Interval x = e;
        x.t_on -= t0;
        x.t_off = std::min(e.t_off, t1) - t0;
        x.*open_at_end = e.*open_at_end || e.t_off > t1;
        out.push_back(x);
    }
    return out;
}

// The records of cycle k: its episodes and conduction stretches, times from its start, cut at its end.
TransientResult cycle_slice(const TransientResult& r, double t0, double period) {
    TransientResult s;
    s.t_end = period;
    const double t1 = t0 + period;
    s.episodes = slice(r.episodes, t0, t1, &ContactEpisode::closed_at_end);
    for (const ContactConduction& c : r.conduction) {
        ContactConduction x = c;
        x.stretches = slice(c.stretches, t0, t1, &ConductionStretch::on_at_end);
        s.conduction.push_back(x);
    }
    return s;
}

// K / H of each contact's support with both wear keys [1/Pa]; NaN for the others.
std::vector<double> wear_factors(const Case& c, const BeamModel& m) {
    std::vector<double> f;
    for (const NamedContact& k : m.contacts) {
        double v = kNaN;
        if (k.entry.table == "supports") {
            const ParameterSet& p = c.supports[k.entry.index].params;
            if (p.numbers.count("wear_coefficient") > 0 && p.numbers.count("hardness") > 0) {
                v = p.number("wear_coefficient") / p.number("hardness");
            }
        }
        f.push_back(v);
    }
    return f;
}

CycleRecord cycle_record(const SimulationRun& run, const Case& one, const std::vector<LedgerContact>& contacts,
                         const std::vector<double>& wear, int k, double period) {
    CycleRecord rec;
    rec.index = k;
    rec.t_start = k * period;
    const TransientResult slice = cycle_slice(run.result, rec.t_start, period);
    rec.switching = switching_ledger(slice, one.electrodes, run.built.model.omega1, contacts, run.summary.group_gap);
    for (const Impact& im : run.summary.impacts) {
        if (im.t_on < rec.t_start || im.t_on >= rec.t_start + period) continue;
        Impact x = im;
        x.t_on -= rec.t_start;
        x.t_off -= rec.t_start;
        rec.impacts.push_back(x);
    }
    rec.damage = contact_damage(rec.impacts);
    for (const ContactConduction& c : slice.conduction) {
        if (const std::optional<ElectricalLedger> l = electrical_ledger(c)) {
            rec.electrical_bounces = l->bounces;
            break;
        }
    }
    if (std::all_of(wear.begin(), wear.end(), [](double f) { return std::isnan(f); })) {
        rec.wear_volume = kNaN;
        return rec;
    }
    for (const ContactEpisode& e : slice.episodes) {
        const double f = wear[static_cast<std::size_t>(e.support)];
        if (!std::isnan(f)) rec.wear_volume += f * e.contact_energy;
    }
    return rec;
}

}  // namespace

CycleTrend cycle_trend(const std::vector<double>& ys) {
    CycleTrend t;
    if (ys.empty()) return t;
    t.first = ys.front();
    t.last = ys.back();
    const double n = static_cast<double>(ys.size());
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < ys.size(); ++i) {
        const double x = static_cast<double>(i);
        sx += x;
        sy += ys[i];
        sxx += x * x;
        sxy += x * ys[i];
    }
    const double d = n * sxx - sx * sx;
    t.slope = d > 0.0 ? (n * sxy - sx * sy) / d : 0.0;
    t.intercept = (sy - t.slope * sx) / n;
    return t;
}

Case cycled_case(const Case& c, const CycleSettings& s) {
    if (s.cycles < 1 || s.cycles > kMaxCycles) {
        throw InputError("--cycles " + std::to_string(s.cycles) + ": must be a whole number from 1 to " +
                         std::to_string(kMaxCycles) + " (the most one study runs)");
    }
    if (!(s.period > 0.0) || !std::isfinite(s.period)) {
        throw InputError("--period: must be above 0 s (or leave it out for the case's solver.horizon)");
    }
    if (c.electrodes.empty()) throw InputError("electrodes: the cycles study drives the switch by its electrodes' voltage; the case has none");
    Case r = c;
    for (std::size_t k = 0; k < r.electrodes.size(); ++k) {
        Electrode& e = r.electrodes[k];
        const std::string key = "electrodes[" + std::to_string(k) + "].waveform";
        switch (e.waveform.kind) {
            case Waveform::Kind::sine: break;  // periodic already
            case Waveform::Kind::constant:
            case Waveform::Kind::step:
            case Waveform::Kind::given:
                throw InputError(key + ": \"" + waveform_name(e.waveform.kind) +
                                 "\" stays on and does not repeat; the cycles study needs a drive that ends within the "
                                 "period (pulse, ramp, two_step, table) or a sine");
            default:
                e.time = repeated_table(e.time, s.period, s.cycles, key);
                // The repeated g is the drive now: no shape key builds it again.
                e.waveform.kind = Waveform::Kind::given;
                break;
        }
    }
    r.solver.horizon = s.period * s.cycles;
    // The study keeps no time history: two samples, whatever the cycles' number.
    r.solver.output_step = r.solver.horizon;
    // The case's work bounds are one run's, one cycle's here: every cycle gets them.
    r.solver.max_steps = c.solver.max_steps * s.cycles;
    r.solver.max_events = c.solver.max_events * s.cycles;
    return r;
}

CyclesResult run_cycles(const Case& c, CycleSettings s, const std::function<void(int)>& progress) {
    if (s.period == 0.0) s.period = c.solver.horizon;
    const Case cycled = cycled_case(c, s);
    SimulationOptions o;
    o.history = false;
    o.energy = false;
    int reported = 0;
    if (progress) {
        o.progress = [&](double t) {
            const int done = std::min(s.cycles, static_cast<int>(t / s.period));
            if (done > reported) progress(reported = done);
        };
    }
    const SimulationRun run = run_simulation(cycled, o);
    CyclesResult out;
    out.settings = s;
    out.steps = run.result.stats.steps;
    out.method = run.result.stats.method;
    // One cycle's drive, for the switching ledger's voltage window.
    Case one = c;
    one.solver.horizon = s.period;
    const std::vector<LedgerContact> contacts = ledger_contacts(c, run.built.model);
    const std::vector<double> wear = wear_factors(c, run.built.model);
    out.wear = std::any_of(wear.begin(), wear.end(), [](double f) { return !std::isnan(f); });
    out.total_wear_volume = out.wear ? 0.0 : kNaN;
    std::vector<double> energy, bounces, force;
    for (int k = 0; k < s.cycles; ++k) {
        CycleRecord rec = cycle_record(run, one, contacts, wear, k, s.period);
        out.total_contact_energy += rec.damage.contact_energy;
        if (out.wear) out.total_wear_volume += rec.wear_volume;
        out.yield_impacts += rec.damage.yield_impacts;
        out.yield_known = out.yield_known || rec.damage.yield_known;
        energy.push_back(rec.damage.contact_energy);
        bounces.push_back(rec.switching.bounces);
        force.push_back(rec.damage.peak_force);
        out.cycles.push_back(std::move(rec));
    }
    out.energy_trend = cycle_trend(energy);
    out.bounce_trend = cycle_trend(bounces);
    out.peak_force_trend = cycle_trend(force);
    if (progress) progress(s.cycles);
    return out;
}

}  // namespace vi
