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

#include "dynamics/signal/event_search.hpp"
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

// The episode peaks' tolerance relative to the peak, and every maximum's relative to the signal's size.
constexpr double kPeakTolerance = 1e-7;
constexpr double kSizeTolerance = 64.0 * std::numeric_limits<double>::epsilon();

// Largest value of f over [0, tau_end] and where, to rel_tol of the maximum itself: 1e-9 for y_max
// and the deepest deflection, 1e-7 for episode peaks (plotted quantities; the FE model itself is
// no closer than ~1e-6 to the continuum at m = 50). Relative to the maximum, not to the signal's
// amplitudes, so that the tiny penetration of a grazing contact is still resolved; never finer than
// roundoff of the signal.
SignalMaximum maximum_over(const ExpSignal& f, double tau_end, const CrossingSearch& cs, int* evals,
                           double floor = -std::numeric_limits<double>::infinity(), double rel_tol = 1e-9,
                           double sign = 1.0) {
    return global_maximum(f, tau_end, kSizeTolerance, rel_tol, cs.t_tol, evals, floor, sign,
                          cs.budget);
}

// y_max is sought everywhere after the first onset; the watched point's deepest deflection only
// while some contact is closed (docs/model.md §14); the contact point's maximum only when it is not
// the watched point itself.
void track_extremes(const PieceSolution& s, double t, double tau_e, int nc, bool in_contact, bool contact_is_watched,
                    const CrossingSearch& cs, int* evals, Extremes& ex) {
    // ex starts at watched_max = contact_max = -inf, watched_min = +inf (set by solve_exact).
    const SignalMaximum top = maximum_over(s.watched_displacement(), tau_e, cs, evals, ex.watched_max);
    SignalMaximum bottom{-ex.watched_min, -1.0};
    if (in_contact) bottom = maximum_over(s.watched_displacement(), tau_e, cs, evals, -ex.watched_min, 1e-9, -1.0);
    if (top.tau >= 0.0) {
        ex.watched_max = top.value;
        ex.watched_max_t = t + top.tau;
    }
    if (bottom.tau >= 0.0) {
        ex.watched_min = -bottom.value;
        ex.watched_min_t = t + bottom.tau;
    }
    if (nc > 0 && !contact_is_watched) {
        ex.contact_max = maximum_over(s.contact_displacement(0), tau_e, cs, evals, ex.contact_max).value;
    } else if (nc > 0) {
        ex.contact_max = ex.watched_max;
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
        const std::string& k = ce.name;
        std::ostringstream msg;
        msg << "transient: " << k << at << ": its damper (Cc = " << ce.damping << " N s/m, Cc/Kc = " << ce.damping / ce.stiffness * 1e6
            << " us) stops the contact point like a plastic stop, and the sign of its force at the opening is roundoff; lower "
            << k << ".damping_ratio (or .damping) or use fewer beam.elements";
        return msg.str();
    }
    return "transient: " + (who >= 0 ? p.contacts[static_cast<std::size_t>(who)].name : std::string("a support")) + at +
           "; give the supports some damping (damping_ratio) or move them apart";
}

// The piece of one contact state from t0; a state that cannot be decomposed is reported with the
// time and the closed contacts, which is what the caller (or the user) needs to place it.
const PieceSolution& piece_at(ExactModel& model, const PiecewiseLinearProblem& p, const std::vector<bool>& active,
                              const Eigen::VectorXd& x, double t0, double t1) {
    try {
        return model.piece(active, x, t0, t1);
    } catch (const NotDiagonalisable& e) {
        std::string closed;
        for (std::size_t c = 0; c < active.size(); ++c) {
            if (active[c]) closed += (closed.empty() ? "" : ", ") + p.contacts[c].name;
        }
        throw NotDiagonalisable(std::string(e.what()) + " at t = " + std::to_string(t0 * 1e6) + " us, closed: " +
                                (closed.empty() ? std::string("none") : closed));
    }
}

// One run of the exact solver: the piece of the current contact state from t, its events, its
// samples, the switch that ends it, until the horizon.
class ExactRun {
public:
    ExactRun(const PiecewiseLinearProblem& p, const TransientOptions& o, const ExactOptions& settings);
    TransientResult run();

private:
    void start();
    // Plays one piece from t_ to its end (an event, a breakpoint, the horizon); false when the motion
    // came to rest and the rest of the horizon was sampled.
    bool advance();
    [[nodiscard]] double piece_end() const;
    [[nodiscard]] bool resting(const PieceSolution& s, double piece_end);
    // TransientOptions::stop_when asked to end the run here (t_end becomes t_).
    [[nodiscard]] bool stop_asked(const PieceSolution& s);
    void finish_at_rest(const PieceSolution& s, double span);
    void locate_events(const PieceSolution& s, double span, const std::vector<double>& from);
    void resolve_repeated_switch(const PieceSolution& s, double span, std::vector<double>& from);
    void sample_piece(const PieceSolution& s);
    // The whole beam at the sample next_sample_ (tau into the piece) when it is a frame of the field.
    void record_field(const PieceSolution& s, double tau);
    // e: the piece's exponentials at its end (its impulse integral takes them).
    void grow_episodes(const PieceSolution& s, const Eigen::VectorXcd& e);
    void count_zero_length_piece();
    // e: as for grow_episodes.
    void switch_contact(const PieceSolution& s, const Eigen::VectorXcd& e);
    void finish();
    void open_episode(int c, double t, double v_in);
    [[nodiscard]] bool peaks_needed(const PieceSolution& s, int c);

    const PiecewiseLinearProblem& p_;
    const TransientOptions& o_;
    TransientResult res_;
    Clock::time_point t_base_;
    ExactModel model_;
    double base_s_ = 0.0;  // decomposition time of the base modes [s]
    int nc_ = 0;
    CrossingSearch cs_;
    long steps_left_ = 0;
    std::vector<bool> active_;
    Eigen::VectorXd x_;
    bool contact_is_watched_ = false;
    std::vector<int> open_;  // each contact's open episode, -1 for none
    // Each contact's open episode: the level its penetration peak is only compared with
    // (TransientOptions::peak_level; -inf: peaks in full), and whether a piece of it went unscanned.
    std::vector<double> peak_level_;
    std::vector<bool> peak_skipped_;
    std::vector<double> breaks_;
    double dt_out_ = 0.0;
    long n_samples_ = 0;
    long next_sample_ = 0;
    EnergyLedger ledger_;
    int zero_length_run_ = 0;
    int zero_length_contact_ = -1;  // the one contact switching in that run, or -2 for several
    UnprovenSteps unproven_;
    double t_ = 0.0;
    long pieces_ = 0;
    double largest_motion_ = 0.0;
    std::vector<double> penetration_scale_;
    int last_switch_ = -1;  // the contact that switched last, and when
    double last_switch_t_ = -1.0;
    // The piece being played: where its first event lies and whose (-1: none, or a release).
    double tau_e_ = 0.0;
    int who_ = -1;
    // What a time limit reached during the run reports (model/run_control.hpp): the current piece
    // (null while the next is made: the last may leave the cache) and the last one's length.
    const PieceSolution* piece_ = nullptr;
    double last_piece_ = std::numeric_limits<double>::quiet_NaN();
};

ExactRun::ExactRun(const PiecewiseLinearProblem& p, const TransientOptions& o, const ExactOptions& settings)
    : p_(p), o_(o), t_base_(Clock::now()), model_(p, o.energy, settings.state_cache_bytes) {
    // Decomposition time: the base modes here, each contact state inside the model (on first use).
    base_s_ = seconds_since(t_base_);
    res_.stats.method = "exact";
    res_.t_end = p.t_end;
    nc_ = static_cast<int>(p.contacts.size());
    const double period1 = 2.0 * std::numbers::pi / model_.base().omega[0];
    cs_.h_min = settings.h_min_periods * period1;
    steps_left_ = o.max_steps;
    cs_.budget = &steps_left_;

    active_ = p.active0;
    if (active_.size() != p.contacts.size()) active_.assign(p.contacts.size(), false);
    x_ = model_.initial_state(p.q0, p.v0);

    contact_is_watched_ = nc_ > 0 && p.contacts.front().dof == p.watched_dof;
    res_.extremes.watched_max = res_.extremes.contact_max = -std::numeric_limits<double>::infinity();
    res_.extremes.watched_min = std::numeric_limits<double>::infinity();
    open_.assign(static_cast<std::size_t>(nc_), -1);
    peak_level_.assign(static_cast<std::size_t>(nc_), -std::numeric_limits<double>::infinity());
    peak_skipped_.assign(static_cast<std::size_t>(nc_), false);

    for (const LoadTerm& l : p.loads) {
        for (double b : l.time.breakpoints(0.0, p.t_end)) breaks_.push_back(b);
    }
    std::sort(breaks_.begin(), breaks_.end());

    dt_out_ = p.output_step > 0 ? p.output_step : p.t_end / 2000.0;
    n_samples_ = o.history ? static_cast<long>(std::floor(p.t_end / dt_out_ * (1 + 1e-12))) + 1 : 0;
    penetration_scale_.assign(static_cast<std::size_t>(nc_), 0.0);
}

void ExactRun::open_episode(int c, double t, double v_in) {
    ContactEpisode e;
    e.support = c;
    e.t_on = t;
    e.v_in = v_in;
    const auto k = static_cast<std::size_t>(c);
    open_[k] = static_cast<int>(res_.episodes.size());
    res_.episodes.push_back(e);
    peak_level_[k] = o_.peak_level ? o_.peak_level(res_.episodes) : -std::numeric_limits<double>::infinity();
    peak_skipped_[k] = false;
    if (peak_level_[k] > -std::numeric_limits<double>::infinity()) {
        res_.episodes.back().peak_force = res_.episodes.back().peak_penetration = std::numeric_limits<double>::quiet_NaN();
    }
}

// Whether the open episode of contact c needs its peaks over this piece in full: not while its
// penetration's comparison with the level its caller reads is settled without them.
bool ExactRun::peaks_needed(const PieceSolution& s, int c) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const auto k = static_cast<std::size_t>(c);
    double& level = peak_level_[k];
    if (level == -kInf) return true;
    if (level == kInf) return false;
    ContactEpisode& ep = res_.episodes[static_cast<std::size_t>(open_[k])];
    const LevelComparison cmp = compare_with_level(s.penetration(c), tau_e_, level, kSizeTolerance, kPeakTolerance,
                                                   cs_.t_tol, &res_.stats.steps, cs_.budget);
    if (cmp.outcome == LevelComparison::below) {
        peak_skipped_[k] = true;
        return false;
    }
    if (cmp.outcome == LevelComparison::above) {
        // Above for good: a value seen stands for the peak, and nothing more is needed of it.
        ep.peak_penetration = cmp.seen;
        level = kInf;
        return false;
    }
    // Only the full search can tell: from here on in full, from the values an episode starts
    // with (the force peak stays unknown when an earlier piece was skipped).
    level = -kInf;
    ep.peak_penetration = 0.0;
    if (!peak_skipped_[k]) ep.peak_force = 0.0;
    return true;
}

// The contacts closed at t = 0 open their episodes; the initial ledger.
void ExactRun::start() {
    const PieceSolution& first = piece_at(model_, p_, active_, x_, 0.0, p_.t_end);
    for (int c = 0; c < nc_; ++c) {
        if (active_[static_cast<std::size_t>(c)]) open_episode(c, 0.0, first.contact_velocity(c).value(0.0));
    }
    if (o_.energy) res_.initial_energy = first.energy_at(0.0, ledger_);
}

// The next load breakpoint after t, or the horizon.
double ExactRun::piece_end() const {
    const auto bit = std::upper_bound(breaks_.begin(), breaks_.end(), t_ * (1 + 1e-15));
    return bit == breaks_.end() ? p_.t_end : std::min(p_.t_end, *bit);
}

// At rest: with nothing left to change the forcing, a motion whose energy about this piece's
// equilibrium is below roundoff of the largest motion seen (amplitude 1e-15) has nothing left to do
// but decay. Searching on would only chase contact switches at roundoff (a zero-gap support, where
// the equilibrium lies on the switching surface, after a few thousand periods); the rest of the
// horizon is this piece, sampled, and the summary says from when.
// A closed contact whose equilibrium force is at roundoff (the equilibrium on its switching surface)
// is not resting on it: the roundoff switch that opens it comes next, and the rest is declared in
// the open state, so that a beam merely touching a zero-gap support at rest does not count as
// lasting contact.
bool ExactRun::resting(const PieceSolution& s, double end) {
    bool firm = true;
    for (int c = 0; c < nc_; ++c) {
        const ExpSignal& d = s.penetration(c);
        auto& scale = penetration_scale_[static_cast<std::size_t>(c)];
        scale = std::max(scale, d.bound(0.0, 0.0, 0));
        if (active_[static_cast<std::size_t>(c)] && constant_part(d) <= kFirmPenetration * scale) firm = false;
    }
    const double motion = s.motion_energy();
    if (motion < 0.0) return false;
    largest_motion_ = std::max(largest_motion_, motion);
    return firm && end == p_.t_end && motion <= kRestEnergy * largest_motion_;
}

bool ExactRun::stop_asked(const PieceSolution& s) {
    if (!o_.stop_when) return false;
    bool open = true;
    for (int c = 0; c < nc_ && open; ++c) open = !active_[static_cast<std::size_t>(c)] && !s.waits_for_release(c);
    if (!o_.stop_when(RunSoFar{t_, res_.episodes, res_.extremes, open, s.motion_energy()})) return false;
    res_.t_end = t_;
    return true;
}

void ExactRun::finish_at_rest(const PieceSolution& s, double span) {
    while (next_sample_ < n_samples_) {
        const double ts = std::min(next_sample_ * dt_out_, p_.t_end);
        s.sample(ts - t_, ts, active_, res_.history, o_.energy, ledger_);
        record_field(s, ts - t_);
        if ((++next_sample_ & 1023) == 0) check_run();
    }
    if (o_.energy) s.accumulate_dissipation(span, ledger_);
    x_ = s.state_at(span);
    res_.stats.at_rest_from = t_;
    t_ = p_.t_end;
}

// The first event of the piece: a contact switching (who_ >= 0) or a contact done waiting for its
// release (who_ = -1); `from[c]` is where the search for contact c starts.
void ExactRun::locate_events(const PieceSolution& s, double span, const std::vector<double>& from) {
    tau_e_ = span;
    who_ = -1;
    for (int c = 0; c < nc_; ++c) {
        const double tau0 = std::min(from[static_cast<std::size_t>(c)], tau_e_);
        const auto hit = first_upcrossing(s.event_function(c), tau0, tau_e_, cs_, &res_.stats.steps, &unproven_);
        if (hit && *hit <= tau_e_) {
            tau_e_ = *hit;
            who_ = c;
        }
        if (s.waits_for_release(c)) {
            // d reaching 0 only changes which function is watched: the piece ends, the state stays.
            const auto out = first_upcrossing(s.release_function(c), tau0, tau_e_, cs_, &res_.stats.steps, &unproven_);
            if (out && *out < tau_e_) {
                tau_e_ = *out;
                who_ = -1;
            }
        }
    }
}

// The contact that has just switched wants to switch back at once: a tangency. Where the state just
// entered is the consistent one, its search starts again past the tangency.
void ExactRun::resolve_repeated_switch(const PieceSolution& s, double span, std::vector<double>& from) {
    if (!(who_ >= 0 && who_ == last_switch_ && t_ == last_switch_t_ && tau_e_ <= cs_.t_tol)) return;
    const std::size_t w = static_cast<std::size_t>(who_);
    const auto tg = resolve_tangency(s.contact_force(who_), s.penetration(who_), span, cs_.h_min, cs_.budget);
    if (tg && tg->closed != active_[w]) return;
    from[w] = tg ? tg->tau : span;
    ++unproven_.count;
    unproven_.excess = std::max(unproven_.excess, tg ? tg->excess : 0.0);
    ++res_.stats.tangencies;
    locate_events(s, span, from);
}

void ExactRun::record_field(const PieceSolution& s, double tau) {
    if (!is_field_sample(next_sample_, o_.field_every, n_samples_)) return;
    const BaseModes& b = model_.base();
    const Eigen::VectorXd q = b.phi * s.state_at(tau).head(b.n);
    res_.history.field_sample.push_back(static_cast<std::size_t>(next_sample_));
    res_.history.field_q.emplace_back(q.data(), q.data() + q.size());
}

// The samples up to the piece's end (the one at its end belongs to the next piece, but the last).
void ExactRun::sample_piece(const PieceSolution& s) {
    if (!o_.energy && o_.field_every == 0) {
        // Without the ledger or field frames, up to 1024 samples at a time (the recurrence's runs
        // computed together), watching the stop flag between them.
        thread_local std::vector<double> tau, t_abs;
        for (bool more = true; more;) {
            tau.clear();
            t_abs.clear();
            while (next_sample_ + static_cast<long>(tau.size()) < n_samples_ && tau.size() < 1024) {
                const double ts = std::min((next_sample_ + static_cast<long>(tau.size())) * dt_out_, p_.t_end);
                if (ts > t_ + tau_e_ || (ts == t_ + tau_e_ && t_ + tau_e_ < p_.t_end)) break;
                tau.push_back(ts - t_);
                t_abs.push_back(ts);
            }
            more = tau.size() == 1024;
            if (!tau.empty()) s.sample_many(tau.data(), t_abs.data(), static_cast<int>(tau.size()), active_, res_.history);
            next_sample_ += static_cast<long>(tau.size());
            if (more) check_run();
        }
        return;
    }
    while (next_sample_ < n_samples_) {
        const double ts = std::min(next_sample_ * dt_out_, p_.t_end);
        if (ts > t_ + tau_e_ || (ts == t_ + tau_e_ && t_ + tau_e_ < p_.t_end)) break;
        s.sample(ts - t_, ts, active_, res_.history, o_.energy, ledger_);
        record_field(s, ts - t_);
        // A long flight sampled finely is one piece of many samples: watch the stop flag there too.
        if ((++next_sample_ & 1023) == 0) check_run();
    }
}

// The open episodes' impulse and peaks over the piece, and the extremes.
void ExactRun::grow_episodes(const PieceSolution& s, const Eigen::VectorXcd& e_end) {
    for (int c = 0; c < nc_; ++c) {
        const int e = open_[static_cast<std::size_t>(c)];
        if (e < 0) continue;
        ContactEpisode& ep = res_.episodes[static_cast<std::size_t>(e)];
        const ExpSignal& F = s.contact_force(c);
        ep.impulse += F.integral(tau_e_, e_end);
        if (!peaks_needed(s, c)) continue;
        if (!peak_skipped_[static_cast<std::size_t>(c)]) {
            ep.peak_force = maximum_over(F, tau_e_, cs_, &res_.stats.steps, ep.peak_force, kPeakTolerance).value;
        }
        ep.peak_penetration = maximum_over(s.penetration(c), tau_e_, cs_, &res_.stats.steps, ep.peak_penetration, kPeakTolerance).value;
    }
    if (!res_.episodes.empty() && tau_e_ > 0.0) {
        const bool in_contact = std::find(active_.begin(), active_.end(), true) != active_.end();
        track_extremes(s, t_, tau_e_, nc_, in_contact, contact_is_watched_, cs_, &res_.stats.steps, res_.extremes);
    }
}

// Only a contact set that keeps switching at one instant, with every tangency resolved, comes here
// 50 times: two contacts whose states decide each other, or one whose damper is so strong for the
// mesh (a plastic stop: Cc far above the nearest element's critical damping) that the sign of its
// force at the opening is roundoff. Both are ill-posed.
void ExactRun::count_zero_length_piece() {
    if (tau_e_ > cs_.t_tol) {
        zero_length_run_ = 0;
        zero_length_contact_ = -1;
        return;
    }
    if (who_ >= 0) zero_length_contact_ = zero_length_run_ == 0 || zero_length_contact_ == who_ ? who_ : -2;
    if (++zero_length_run_ > 50) throw EndlessSwitching(endless_switching_message(p_, zero_length_contact_, who_, t_));
}

// Contact who_ switches at t_ (its new state holds from the next piece on).
void ExactRun::switch_contact(const PieceSolution& s, const Eigen::VectorXcd& e) {
    last_switch_ = who_;
    last_switch_t_ = t_;
    ++res_.stats.events;
    const double v_contact = s.contact_velocity(who_).value(tau_e_, e);
    const std::size_t w = static_cast<std::size_t>(who_);
    // A damped contact opens (F = 0) while still compressed (d > 0): the massless Kelvin-Voigt
    // element then relaxes through its damper, so its spring energy is booked as contact
    // dissipation; a closing at d > 0 books it back (docs/model.md).
    const double d_switch = std::max(0.0, s.penetration(who_).value(tau_e_, e));
    const double stored = 0.5 * p_.contacts[w].stiffness * d_switch * d_switch;
    ledger_.contact_dissipated += active_[w] ? stored : -stored;
    if (active_[w]) {
        ContactEpisode& ep = res_.episodes[static_cast<std::size_t>(open_[w])];
        ep.t_off = t_;
        ep.v_out = v_contact;
        open_[w] = -1;
    } else {
        open_episode(who_, t_, v_contact);
    }
    active_[w] = !active_[w];
}

bool ExactRun::advance() {
    check_run();
    if (++pieces_ > o_.max_events) {
        throw WorkLimitReached("more than solver.max_events = " + std::to_string(o_.max_events) +
                               " contact switches and load breakpoints before the horizon (at t = " +
                               std::to_string(t_ * 1e6) + " us; raise solver.max_events or shorten solver.horizon)");
    }
    const double end = piece_end();
    const auto t_piece = Clock::now();
    const double dec_before = model_.decomposition_seconds();
    piece_ = nullptr;
    const PieceSolution& s = piece_at(model_, p_, active_, x_, t_, end);
    piece_ = &s;
    res_.stats.propagation_s += seconds_since(t_piece) - (model_.decomposition_seconds() - dec_before);
    const double span = end - t_;
    if (stop_asked(s)) return false;
    if (resting(s, end)) {
        finish_at_rest(s, span);
        return false;
    }
    // Roots to a few ulps of the absolute time (and of the piece's own clock): far below the 1e-10
    // relative time tolerance required, whatever the first free period (a single mass on a weak
    // spring has one of minutes).
    cs_.t_tol = 4.0 * std::numeric_limits<double>::epsilon() * (t_ + span);

    const auto t_ev = Clock::now();
    // Where the search for each contact starts (after a resolved tangency, past it).
    std::vector<double> from(static_cast<std::size_t>(nc_), 0.0);
    locate_events(s, span, from);
    resolve_repeated_switch(s, span, from);
    res_.stats.event_location_s += seconds_since(t_ev);

    const auto t_prop = Clock::now();
    sample_piece(s);
    const Eigen::VectorXcd e_end = s.exponentials(tau_e_);
    grow_episodes(s, e_end);
    if (o_.energy) s.accumulate_dissipation(tau_e_, ledger_);
    x_ = s.state_at(tau_e_, e_end);
    res_.stats.propagation_s += seconds_since(t_prop);
    ++res_.stats.steps;
    t_ += tau_e_;
    last_piece_ = tau_e_;
    count_zero_length_piece();
    if (who_ >= 0) switch_contact(s, e_end);
    return true;
}

// Episodes still open at the horizon, the final ledger, the statistics.
void ExactRun::finish() {
    for (int c = 0; c < nc_; ++c) {
        const int e = open_[static_cast<std::size_t>(c)];
        if (e < 0) continue;
        ContactEpisode& ep = res_.episodes[static_cast<std::size_t>(e)];
        ep.t_off = res_.t_end;
        ep.closed_at_end = true;
    }
    if (o_.energy) {
        const PieceSolution& last = model_.piece(active_, x_, res_.t_end, res_.t_end);
        res_.final_energy = last.energy_at(0.0, ledger_);
    }
    res_.stats.unproven_steps = unproven_.count;
    res_.stats.unproven_excess = unproven_.excess;
    res_.stats.decompositions = model_.decompositions();
    res_.stats.decomposition_s = base_s_ + model_.decomposition_seconds();
    std::sort(res_.episodes.begin(), res_.episodes.end(),
              [](const ContactEpisode& a, const ContactEpisode& b) { return a.t_on < b.t_on; });
}

TransientResult ExactRun::run() {
    start();
    const ProgressNote note([this] { return exact_progress(t_, p_.t_end, pieces_, last_piece_, piece_, nc_); });
    while (t_ < p_.t_end && advance()) {
    }
    finish();
    return std::move(res_);
}

}  // namespace

TransientResult solve_exact(const PiecewiseLinearProblem& p, const TransientOptions& o, const ExactOptions& settings) {
    if (p.size() == 0) throw std::runtime_error("transient: the model has no free bending DOF");
    if (!(p.t_end > 0.0)) throw std::runtime_error("transient: the horizon must be positive");
    return ExactRun(p, o, settings).run();
}

TransientResult solve_exact(const TransientProblem& p, const TransientOptions& o, const ExactOptions& settings) {
    return solve_exact(piecewise_linear_form(p), o, settings);
}

}  // namespace vi
