#include "dynamics/exact/exact_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <limits>
#include <sstream>
#include <string>

#include "dynamics/exact/event_search.hpp"
#include "dynamics/exact/exact_state.hpp"
#include "dynamics/piecewise_linear_form.hpp"
#include "dynamics/exact/state_modes.hpp"
#include "model/number_format.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

using Clock = std::chrono::steady_clock;
// The motion counts as at rest below this fraction of the largest motion energy seen (an amplitude
// 1e-15 of the largest: the roundoff of the state itself).
constexpr double kRestEnergy = 1e-30;
// A closed contact rests firmly when its equilibrium penetration exceeds this fraction of the
// largest penetration or gap it has had: far above roundoff (1e-16), far below any prestress.
constexpr double kFirmPenetration = 1e-9;
// The constant part of a signal in a piece with constant forcing: its value at equilibrium.
double constant_part(const ExpSignal& f) {
    double v = 0.0;
    for (const ExpTerm& term : f.terms) {
        if (term.s == cd(0.0) && term.power == 0) v += term.coef.real();
    }
    return v;
}

// Largest value of f over [0, tau_end] and where, to rel_tol of the maximum itself: 1e-9 for y_max
// and the deepest deflection, 1e-7 for episode peaks (plotted quantities; the FE model itself is
// no closer than ~1e-6 to the continuum at m = 50). Relative to the maximum, not to the signal's
// amplitudes, so that the tiny penetration of a grazing contact is still resolved; never finer than
// roundoff of the signal.
SignalMaximum maximum_over(const ExpSignal& f, double tau_end, const CrossingSearch& cs, int* evals,
                           double floor = -std::numeric_limits<double>::infinity(), double rel_tol = 1e-9,
                           double sign = 1.0) {
    return global_maximum(f, tau_end, 64.0 * std::numeric_limits<double>::epsilon(), rel_tol, cs.t_tol, evals, floor, sign,
                          cs.budget);
}

// y_max is sought everywhere after the first onset; the deepest tip deflection only while some
// contact is closed (DESIGN.md: "during impact"); the contact point's maximum only when it is not
// the tip itself.
void track_extremes(const PieceSolution& s, double t, double tau_e, int nc, bool in_contact, bool contact_is_tip,
                    const CrossingSearch& cs, int* evals, Extremes& ex) {
    // ex starts at tip_max = contact_max = -inf, tip_min = +inf (set by solve_exact).
    const SignalMaximum top = maximum_over(s.tip_displacement(), tau_e, cs, evals, ex.tip_max);
    SignalMaximum bottom{-ex.tip_min, -1.0};
    if (in_contact) bottom = maximum_over(s.tip_displacement(), tau_e, cs, evals, -ex.tip_min, 1e-9, -1.0);
    if (top.tau >= 0.0) {
        ex.tip_max = top.value;
        ex.tip_max_t = t + top.tau;
    }
    if (bottom.tau >= 0.0) {
        ex.tip_min = -bottom.value;
        ex.tip_min_t = t + bottom.tau;
    }
    if (nc > 0 && !contact_is_tip) {
        ex.contact_max = maximum_over(s.contact_displacement(0), tau_e, cs, evals, ex.contact_max).value;
    } else if (nc > 0) {
        ex.contact_max = ex.tip_max;
    }
    ex.valid = true;
}

// A contact that switched at this instant and wants to switch back at once sits on a tangency: its
// force F is zero to roundoff with a slope at roundoff too, and the two states' event functions each
// see the other state as the consistent one (the values are noise). Both states share the leading
// term of F's expansion (they differ only by the effect of a force that is itself that small), so
// the sign of F a little ahead decides: the first point tau_j = h_min 4^j at which |F| (or the
// penetration d) is clear of roundoff. Returns that point and whether the contact is closed there
// (F > 0 and d > 0); nullopt when F and d stay at roundoff over the whole piece (nothing decides:
// the contact carries no force either way and the current state is kept).
struct Tangency {
    double tau = 0.0;
    bool closed = false;
    double excess = 0.0;  // largest |F| within roundoff met before tau, relative to F's size
};
std::optional<Tangency> resolve_tangency(const ExpSignal& F, const ExpSignal& d, double span, double h_min, long* budget) {
    constexpr double kEps = std::numeric_limits<double>::epsilon();
    const double f_noise = 64.0 * kEps * std::max(F.bound(0.0, 0.0, 0), std::numeric_limits<double>::min());
    const double d_noise = 64.0 * kEps * std::max(d.bound(0.0, 0.0, 0), std::numeric_limits<double>::min());
    Tangency out;
    for (double tau = std::max(h_min, 1e-300); tau < span * 4.0; tau *= 4.0) {
        charge_evaluations(budget, 2);
        const double at = std::min(tau, span);
        const double f = F.value(at);
        const double pen = d.value(at);
        if (std::abs(f) > f_noise || std::abs(pen) > d_noise) {
            out.tau = at;
            out.closed = f > 0.0 && pen > 0.0;
            return out;
        }
        out.excess = std::max(out.excess, std::abs(f) / (f_noise / (64.0 * kEps)));
        if (at == span) break;
    }
    return std::nullopt;
}

// The time reached, the pieces so far and the last one's length, and the closest contact gap at the
// current piece's start (negative: a penetration): computed only when a time limit is reached.
std::string exact_progress(double t, double t_end, long pieces, double last_piece, const PieceSolution* piece, int contacts) {
    std::string out = "the exact solver had reached t = " + significant(t, 6) + " s of " + significant(t_end, 6) + " s in " +
                      std::to_string(pieces) + " pieces";
    if (std::isfinite(last_piece)) out += "; last piece " + significant(last_piece, 3) + " s";
    double gap = std::numeric_limits<double>::infinity();
    for (int c = 0; piece != nullptr && c < contacts; ++c) gap = std::min(gap, -piece->penetration(c).value(0.0));
    if (std::isfinite(gap)) out += "; closest contact gap " + significant(gap, 3) + " m (negative: penetration)";
    return out;
}

// What to change when contact states repeat at one instant (see the caller).
std::string endless_switching_message(const PiecewiseLinearProblem& p, int only, int who, double t) {
    const std::string at = " switches without end at t = " + std::to_string(t * 1e6) + " us (zero-length contact states repeat)";
    if (only >= 0) {
        const ContactElement& ce = p.contacts[static_cast<std::size_t>(only)];
        const std::string k = "supports[" + std::to_string(only) + "]";
        std::ostringstream msg;
        msg << "transient: " << k << at << ": its damper (Cc = " << ce.damping << " N s/m, Cc/Kc = " << ce.damping / ce.stiffness * 1e6
            << " us) stops the contact point like a plastic stop, and the sign of its force at the opening is roundoff; lower "
            << k << ".damping_ratio (or .damping) or use fewer beam.elements";
        return msg.str();
    }
    return "transient: " + (who >= 0 ? "supports[" + std::to_string(who) + "]" : std::string("a support")) + at +
           "; give the supports some damping (damping_ratio) or move them apart";
}

// The piece of one contact state from t0; a state that cannot be decomposed is reported with the
// time and the closed contacts, which is what the caller (or the user) needs to place it.
const PieceSolution& piece_at(ExactModel& model, const std::vector<bool>& active, const Eigen::VectorXd& x, double t0,
                              double t1) {
    try {
        return model.piece(active, x, t0, t1);
    } catch (const NotDiagonalisable& e) {
        std::string closed;
        for (std::size_t c = 0; c < active.size(); ++c) {
            if (active[c]) closed += (closed.empty() ? "" : ", ") + ("supports[" + std::to_string(c) + "]");
        }
        throw NotDiagonalisable(std::string(e.what()) + " at t = " + std::to_string(t0 * 1e6) + " us, closed: " +
                                (closed.empty() ? std::string("none") : closed));
    }
}

}  // namespace

TransientResult solve_exact(const PiecewiseLinearProblem& p, const ExactOptions& o) {
    if (p.size() == 0) throw std::runtime_error("transient: the model has no free bending DOF");
    if (!(p.t_end > 0.0)) throw std::runtime_error("transient: the horizon must be positive");
    TransientResult res;
    res.stats.method = "exact";
    res.t_end = p.t_end;
    // Decomposition time: the base modes here, each contact state inside the model (on first use).
    const auto t_base = Clock::now();
    ExactModel model(p, o.energy, o.state_cache_bytes);
    const double base_s = seconds_since(t_base);

    const int nc = static_cast<int>(p.contacts.size());
    const double period1 = 2.0 * std::numbers::pi / model.base().omega[0];
    CrossingSearch cs;
    cs.h_min = o.h_min_periods * period1;
    long steps_left = o.max_steps;
    cs.budget = &steps_left;

    std::vector<bool> active = p.active0;
    if (active.size() != p.contacts.size()) active.assign(p.contacts.size(), false);
    Eigen::VectorXd x = model.initial_state(p.q0, p.v0);

    const bool contact_is_tip = nc > 0 && p.contacts.front().dof == p.tip_dof;
    res.extremes.tip_max = res.extremes.contact_max = -std::numeric_limits<double>::infinity();
    res.extremes.tip_min = std::numeric_limits<double>::infinity();
    std::vector<int> open(static_cast<std::size_t>(nc), -1);
    auto open_episode = [&](int c, double t, double v_in) {
        ContactEpisode e;
        e.support = c;
        e.t_on = t;
        e.v_in = v_in;
        open[static_cast<std::size_t>(c)] = static_cast<int>(res.episodes.size());
        res.episodes.push_back(e);
    };

    std::vector<double> breaks;
    for (const LoadTerm& l : p.loads) {
        for (double b : l.time.breakpoints(0.0, p.t_end)) breaks.push_back(b);
    }
    std::sort(breaks.begin(), breaks.end());

    const double dt_out = p.output_step > 0 ? p.output_step : p.t_end / 2000.0;
    const long n_samples = o.history ? static_cast<long>(std::floor(p.t_end / dt_out * (1 + 1e-12))) + 1 : 0;
    long next_sample = 0;
    EnergyLedger ledger;
    int zero_length_run = 0;
    int zero_length_support = -1;  // the one support switching in that run, or -2 for several
    UnprovenSteps unproven;
    double t = 0.0;
    long pieces = 0;
    double largest_motion = 0.0;
    std::vector<double> penetration_scale(static_cast<std::size_t>(nc), 0.0);
    int last_switch = -1;       // the contact that switched last, and when
    double last_switch_t = -1.0;

    {
        const PieceSolution& first = piece_at(model, active, x, 0.0, p.t_end);
        for (int c = 0; c < nc; ++c) {
            if (active[static_cast<std::size_t>(c)]) open_episode(c, 0.0, first.contact_velocity(c).value(0.0));
        }
        if (o.energy) res.initial_energy = first.energy_at(0.0, ledger);
    }

    // A time limit reached in here says how far the transient got (model/run_control.hpp).
    const PieceSolution* piece = nullptr;
    double last_piece = std::numeric_limits<double>::quiet_NaN();
    const ProgressNote note([&] { return exact_progress(t, p.t_end, pieces, last_piece, piece, nc); });
    while (t < p.t_end) {
        check_run();
        if (++pieces > o.max_events) {
            throw WorkLimitReached("more than solver.max_events = " + std::to_string(o.max_events) +
                                   " contact switches and load breakpoints before the horizon (at t = " +
                                   std::to_string(t * 1e6) + " us; raise solver.max_events or shorten solver.horizon)");
        }
        const auto bit = std::upper_bound(breaks.begin(), breaks.end(), t * (1 + 1e-15));
        const double piece_end = bit == breaks.end() ? p.t_end : std::min(p.t_end, *bit);
        const auto t_piece = Clock::now();
        const double dec_before = model.decomposition_seconds();
        piece = nullptr;  // the last piece's solution may leave the cache while the next is made
        const PieceSolution& s = piece_at(model, active, x, t, piece_end);
        piece = &s;
        res.stats.propagation_s += seconds_since(t_piece) - (model.decomposition_seconds() - dec_before);
        const double span = piece_end - t;
        // At rest: with nothing left to change the forcing, a motion whose energy about this piece's
        // equilibrium is below roundoff of the largest motion seen (amplitude 1e-15) has nothing left
        // to do but decay. Searching on would only chase contact switches at roundoff (a zero-gap
        // support, where the equilibrium lies on the switching surface, after a few thousand periods);
        // the rest of the horizon is this piece, sampled, and the summary says from when.
        // A closed contact whose equilibrium force is at roundoff (the equilibrium on its switching
        // surface) is not resting on it: the roundoff switch that opens it comes next, and the rest
        // is declared in the open state, so that a beam merely touching a zero-gap support at rest
        // does not count as lasting contact.
        bool firm = true;
        for (int c = 0; c < nc; ++c) {
            const ExpSignal& d = s.penetration(c);
            auto& scale = penetration_scale[static_cast<std::size_t>(c)];
            scale = std::max(scale, d.bound(0.0, 0.0, 0));
            if (active[static_cast<std::size_t>(c)] && constant_part(d) <= kFirmPenetration * scale) firm = false;
        }
        if (const double motion = s.motion_energy(); motion >= 0.0) {
            largest_motion = std::max(largest_motion, motion);
            if (firm && piece_end == p.t_end && motion <= kRestEnergy * largest_motion) {
                while (next_sample < n_samples) {
                    const double ts = std::min(next_sample * dt_out, p.t_end);
                    s.sample(ts - t, ts, active, res.history, o.energy, ledger);
                    if ((++next_sample & 1023) == 0) check_run();
                }
                if (o.energy) s.accumulate_dissipation(span, ledger);
                x = s.state_at(span);
                res.stats.at_rest_from = t;
                t = p.t_end;
                break;
            }
        }
        // Roots to a few ulps of the absolute time (and of the piece's own clock): far below the 1e-10
        // relative time tolerance required, whatever the first free period (a single mass on a weak
        // spring has one of minutes).
        cs.t_tol = 4.0 * std::numeric_limits<double>::epsilon() * (t + span);

        const auto t_ev = Clock::now();
        double tau_e = span;
        int who = -1;
        // `from[c]`: where the search for contact c starts (after a resolved tangency, past it).
        std::vector<double> from(static_cast<std::size_t>(nc), 0.0);
        const auto locate_events = [&]() {
            tau_e = span;
            who = -1;
            for (int c = 0; c < nc; ++c) {
                const double tau0 = std::min(from[static_cast<std::size_t>(c)], tau_e);
                const auto hit = first_upcrossing(s.event_function(c), tau0, tau_e, cs, &res.stats.steps, &unproven);
                if (hit && *hit <= tau_e) {
                    tau_e = *hit;
                    who = c;
                }
                if (s.waits_for_release(c)) {
                    // d reaching 0 only changes which function is watched: the piece ends, the state stays.
                    const auto out =
                        first_upcrossing(s.release_function(c), tau0, tau_e, cs, &res.stats.steps, &unproven);
                    if (out && *out < tau_e) {
                        tau_e = *out;
                        who = -1;
                    }
                }
            }
        };
        locate_events();
        if (who >= 0 && who == last_switch && t == last_switch_t && tau_e <= cs.t_tol) {
            const std::size_t w = static_cast<std::size_t>(who);
            const auto tg = resolve_tangency(s.contact_force(who), s.penetration(who), span, cs.h_min, cs.budget);
            const bool keep = !tg || tg->closed == active[w];
            if (keep) {
                // The state just entered is the consistent one: search again from past the tangency.
                from[w] = tg ? tg->tau : span;
                ++unproven.count;
                unproven.excess = std::max(unproven.excess, tg ? tg->excess : 0.0);
                ++res.stats.tangencies;
                locate_events();
            }
        }
        res.stats.event_location_s += seconds_since(t_ev);

        const auto t_prop = Clock::now();
        while (next_sample < n_samples) {
            const double ts = std::min(next_sample * dt_out, p.t_end);
            if (ts > t + tau_e || (ts == t + tau_e && t + tau_e < p.t_end)) break;
            s.sample(ts - t, ts, active, res.history, o.energy, ledger);
            // A long flight sampled finely is one piece of many samples: watch the stop flag there too.
            if ((++next_sample & 1023) == 0) check_run();
        }
        for (int c = 0; c < nc; ++c) {
            const int e = open[static_cast<std::size_t>(c)];
            if (e < 0) continue;
            ContactEpisode& ep = res.episodes[static_cast<std::size_t>(e)];
            const ExpSignal& F = s.contact_force(c);
            ep.impulse += F.integral(tau_e);
            ep.peak_force = maximum_over(F, tau_e, cs, &res.stats.steps, ep.peak_force, 1e-7).value;
            ep.peak_penetration =
                maximum_over(s.penetration(c), tau_e, cs, &res.stats.steps, ep.peak_penetration, 1e-7).value;
        }
        if (!res.episodes.empty() && tau_e > 0.0) {
            const bool in_contact = std::find(active.begin(), active.end(), true) != active.end();
            track_extremes(s, t, tau_e, nc, in_contact, contact_is_tip, cs, &res.stats.steps, res.extremes);
        }
        if (o.energy) s.accumulate_dissipation(tau_e, ledger);
        x = s.state_at(tau_e);
        res.stats.propagation_s += seconds_since(t_prop);
        ++res.stats.steps;
        t += tau_e;
        last_piece = tau_e;
        if (tau_e <= cs.t_tol) {
            // Only a contact set that keeps switching at one instant, with every tangency resolved,
            // comes here 50 times: two contacts whose states decide each other, or one whose damper
            // is so strong for the mesh (a plastic stop: Cc far above the nearest element's critical
            // damping) that the sign of its force at the opening is roundoff. Both are ill-posed.
            if (who >= 0) zero_length_support = zero_length_run == 0 || zero_length_support == who ? who : -2;
            if (++zero_length_run > 50) throw EndlessSwitching(endless_switching_message(p, zero_length_support, who, t));
        } else {
            zero_length_run = 0;
            zero_length_support = -1;
            zero_length_run = 0;
        }
        if (who >= 0) {
            last_switch = who;
            last_switch_t = t;
            ++res.stats.events;
            const double v_contact = s.contact_velocity(who).value(tau_e);
            const std::size_t w = static_cast<std::size_t>(who);
            // A damped contact opens (F = 0) while still compressed (d > 0): the massless Kelvin-Voigt
            // element then relaxes through its damper, so its spring energy is booked as contact
            // dissipation; a closing at d > 0 books it back (docs/model.md).
            const double d_switch = std::max(0.0, s.penetration(who).value(tau_e));
            const double stored = 0.5 * p.contacts[w].stiffness * d_switch * d_switch;
            ledger.contact_dissipated += active[w] ? stored : -stored;
            if (active[w]) {
                ContactEpisode& ep = res.episodes[static_cast<std::size_t>(open[w])];
                ep.t_off = t;
                ep.v_out = v_contact;
                open[w] = -1;
            } else {
                open_episode(who, t, v_contact);
            }
            active[w] = !active[w];
        }
    }
    for (int c = 0; c < nc; ++c) {
        const int e = open[static_cast<std::size_t>(c)];
        if (e < 0) continue;
        ContactEpisode& ep = res.episodes[static_cast<std::size_t>(e)];
        ep.t_off = p.t_end;
        ep.closed_at_end = true;
    }
    if (o.energy) {
        const PieceSolution& last = model.piece(active, x, p.t_end, p.t_end);
        res.final_energy = last.energy_at(0.0, ledger);
    }
    res.stats.unproven_steps = unproven.count;
    res.stats.unproven_excess = unproven.excess;
    res.stats.decompositions = model.decompositions();
    res.stats.decomposition_s = base_s + model.decomposition_seconds();
    std::sort(res.episodes.begin(), res.episodes.end(),
              [](const ContactEpisode& a, const ContactEpisode& b) { return a.t_on < b.t_on; });
    return res;
}

TransientResult solve_exact(const TransientProblem& p, const ExactOptions& o) {
    return solve_exact(piecewise_linear_form(p), o);
}

}  // namespace vi
