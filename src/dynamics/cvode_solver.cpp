#include "dynamics/cvode_solver.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/cvode_system.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

using cvode_detail::CvodeSystem;
using cvode_detail::jac_fn;
using cvode_detail::rhs_fn;
using cvode_detail::root_fn;
using Clock = std::chrono::steady_clock;
constexpr double kEps = std::numeric_limits<double>::epsilon();

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// True when a and b are the same instant up to a few ulps.
bool same_time(double a, double b) {
    return std::abs(a - b) <= 8.0 * kEps * std::max({std::abs(a), std::abs(b), 1e-300});
}

// SUNDIALS objects, freed in reverse order of creation.
struct Sundials {
    SUNContext ctx = nullptr;
    N_Vector y = nullptr, tmp = nullptr, atol = nullptr;
    SUNMatrix A = nullptr;
    SUNLinearSolver LS = nullptr;
    void* mem = nullptr;
    Sundials() = default;
    Sundials(const Sundials&) = delete;
    Sundials& operator=(const Sundials&) = delete;
    ~Sundials() {
        if (mem) CVodeFree(&mem);
        if (LS) SUNLinSolFree(LS);
        if (A) SUNMatDestroy(A);
        if (atol) N_VDestroy(atol);
        if (tmp) N_VDestroy(tmp);
        if (y) N_VDestroy(y);
        if (ctx) SUNContext_Free(&ctx);
    }
};

// Nothing below the command line prints: CVODE's messages are kept for the exception text.
void error_fn(int code, const char* module, const char* function, char* msg, void* ud) {
    if (code < 0) {
        *static_cast<std::string*>(ud) = std::string(module) + "/" + function + ": " + msg;
    }
}

class Driver {
public:
    Driver(const TransientProblem& p, const CvodeOptions& o) : p_(p), o_(o), sys_(p) {}
    TransientResult run();

private:
    void check(int flag, const char* what) const;
    void setup();
    double sample_time(std::size_t k) const;
    void sample_until(double t_lim, bool interpolate);
    void record(double t, const double* y);
    void update_peaks(const double* y);
    void update_extremes(double t, const double* y);
    double handle_roots(double tret);
    double locate_missed_closing(int j, double tret);
    void toggle(double t, const std::vector<int>& which);
    void restart(double t);
    void add_counters();

    const TransientProblem& p_;
    CvodeOptions o_;
    CvodeSystem sys_;
    Sundials s_;
    std::string cvode_message_;
    TransientResult r_;
    std::vector<double> stops_;          // load breakpoints in (0, t_end), then t_end
    std::size_t samples_ = 0, next_sample_ = 0;
    std::vector<bool> active_;
    std::vector<int> open_;              // open episode of each contact, -1 if none
    std::vector<double> impulse_at_onset_;
    // Contact-spring energy that appears or vanishes at a switch: a contact opening with d > 0 (the
    // damped case: F = 0 before d = 0) drops 1/2 Kc d^2 from the ledger's contact_spring. A massless
    // Kelvin-Voigt element left alone relaxes through its damper, which dissipates exactly that, so
    // it is booked as contact_dissipated; a contact closing with d > 0 (F rising through 0) takes it
    // back. Without contact damping both jumps are zero (d = 0 at every switch).
    double jump_ = 0.0;
    long steps_done_ = 0, setups_done_ = 0;
    double t_restart_ = 0.0, last_event_t_ = -1.0;
    double t_done_ = 0.0;                // time of the last return of CVODE (all before is recorded)
    int burst_ = 0;
};

void Driver::check(int flag, const char* what) const {
    if (flag >= 0) return;
    char* name = CVodeGetReturnFlagName(flag);
    std::string msg = std::string("solve_cvode: ") + what + " failed (" + (name ? name : "?") + ")";
    std::free(name);
    if (!cvode_message_.empty()) msg += ": " + cvode_message_;
    throw std::runtime_error(msg);
}

void Driver::setup() {
    const int N = sys_.size();
    if (SUNContext_Create(nullptr, &s_.ctx) != 0) throw std::runtime_error("solve_cvode: SUNContext_Create failed");
    s_.y = N_VNew_Serial(N, s_.ctx);
    s_.tmp = N_VNew_Serial(N, s_.ctx);
    s_.atol = N_VNew_Serial(N, s_.ctx);
    s_.A = SUNDenseMatrix(N, N, s_.ctx);
    if (!s_.y || !s_.tmp || !s_.atol || !s_.A) throw std::runtime_error("solve_cvode: out of memory");
    s_.LS = SUNLinSol_Dense(s_.y, s_.A, s_.ctx);
    s_.mem = CVodeCreate(CV_BDF, s_.ctx);
    if (!s_.LS || !s_.mem) throw std::runtime_error("solve_cvode: CVODE setup failed");
    check(CVodeSetErrHandlerFn(s_.mem, error_fn, &cvode_message_), "CVodeSetErrHandlerFn");

    const Eigen::VectorXd y0 = sys_.initial_state();
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(s_.y), N) = y0;
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(s_.atol), N) = sys_.absolute_tolerances(o_.atol_scale);
    check(CVodeInit(s_.mem, rhs_fn, 0.0, s_.y), "CVodeInit");
    check(CVodeSVtolerances(s_.mem, o_.rtol, s_.atol), "CVodeSVtolerances");
    check(CVodeSetUserData(s_.mem, &sys_), "CVodeSetUserData");
    check(CVodeSetLinearSolver(s_.mem, s_.LS, s_.A), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(s_.mem, jac_fn), "CVodeSetJacFn");
    check(CVodeSetMaxNumSteps(s_.mem, std::min<long>(o_.max_steps, std::numeric_limits<int>::max())), "CVodeSetMaxNumSteps");
    check(CVodeSetMaxHnilWarns(s_.mem, -1), "CVodeSetMaxHnilWarns");
    if (sys_.roots() > 0) {
        check(CVodeRootInit(s_.mem, sys_.roots(), root_fn), "CVodeRootInit");
        check(CVodeSetNoInactiveRootWarn(s_.mem), "CVodeSetNoInactiveRootWarn");
    }
    restart(0.0);  // sets the root directions; a reinit at t0 with y0 is a no-op otherwise
}

double Driver::sample_time(std::size_t k) const {
    if (samples_ == 2 && !(p_.output_step > 0.0)) return k == 0 ? 0.0 : p_.t_end;
    return std::min(static_cast<double>(k) * p_.output_step, p_.t_end);
}

// Records every sample time <= t_lim: at t_lim from the current y, before it from CVODE's
// interpolating polynomial of the last step (dense output; the step sequence is not touched).
void Driver::sample_until(double t_lim, bool interpolate) {
    for (; next_sample_ < samples_ && sample_time(next_sample_) <= t_lim; ++next_sample_) {
        const double ts = sample_time(next_sample_);
        if (!interpolate || same_time(ts, t_lim)) {
            record(ts, N_VGetArrayPointer(s_.y));
        } else {
            check(CVodeGetDky(s_.mem, ts, 0, s_.tmp), "CVodeGetDky");
            record(ts, N_VGetArrayPointer(s_.tmp));
        }
    }
}

void Driver::record(double t, const double* y) {
    TimeHistory& h = r_.history;
    const int n = sys_.dofs();
    h.t.push_back(t);
    h.tip_v.push_back(y[p_.tip_dof]);
    h.tip_velocity.push_back(y[n + p_.tip_dof]);
    for (int j = 0; j < sys_.contacts(); ++j) {
        const auto uj = static_cast<std::size_t>(j);
        h.contact_v[uj].push_back(y[p_.contacts[uj].dof]);
        h.contact_velocity[uj].push_back(sys_.contact_velocity(j, y));
        h.contact_force[uj].push_back(active_[uj] ? sys_.force(j, y) : 0.0);
    }
    h.energy.push_back(sys_.energy(y, jump_));
}

// Peaks: the largest F and d of an episode are at its ends, at an interior maximum (located
// exactly: events 1 and 2 are dd/dt and dF/dt of a closed contact, direction -1) or at a stop
// where dF/dt jumps (another contact switching, a load breakpoint). This runs at every return of
// CVODE (each step, root and stop), so all of those are covered.
// Extremes (y_max, deepest tip deflection, contact point maximum) after the first onset: local
// extrema are roots of the velocities (located by CVODE); values at every return cover the ends.
void Driver::update_extremes(double t, const double* y) {
    if (r_.episodes.empty()) return;
    Extremes& ex = r_.extremes;
    const double tip = y[p_.tip_dof];
    if (!ex.valid) {
        ex.valid = true;
        ex.tip_max = ex.contact_max = -std::numeric_limits<double>::infinity();
        ex.tip_min = std::numeric_limits<double>::infinity();
    }
    if (tip > ex.tip_max) {
        ex.tip_max = tip;
        ex.tip_max_t = t;
    }
    const bool in_contact = std::find(active_.begin(), active_.end(), true) != active_.end();
    if (in_contact && tip < ex.tip_min) {
        ex.tip_min = tip;
        ex.tip_min_t = t;
    }
    if (sys_.contacts() > 0) ex.contact_max = std::max(ex.contact_max, y[p_.contacts.front().dof]);
}

void Driver::update_peaks(const double* y) {
    for (int j = 0; j < sys_.contacts(); ++j) {
        const int e = open_[static_cast<std::size_t>(j)];
        if (e < 0) continue;
        ContactEpisode& ep = r_.episodes[static_cast<std::size_t>(e)];
        ep.peak_force = std::max(ep.peak_force, sys_.force(j, y));
        ep.peak_penetration = std::max(ep.peak_penetration, sys_.penetration(j, y));
    }
}

double Driver::handle_roots(double tret) {
    std::vector<int> info(static_cast<std::size_t>(sys_.roots()), 0);
    check(CVodeGetRootInfo(s_.mem, info.data()), "CVodeGetRootInfo");
    const double* y = N_VGetArrayPointer(s_.y);
    double t_ev = tret;
    std::vector<int> which;
    // Guard: an open contact at a maximum of d with d > 0 and F > 0 closed earlier in this step
    // without CVODE seeing the closing function change sign at the step ends.
    for (int j = 0; j < sys_.contacts(); ++j) {
        if (active_[static_cast<std::size_t>(j)] || info[static_cast<std::size_t>(3 * j + 1)] == 0) continue;
        if (sys_.closing_function(j, y) <= 0.0) continue;
        const double tc = locate_missed_closing(j, tret);
        if (which.empty() || tc < t_ev) {
            which = {j};
            t_ev = tc;
        } else if (same_time(tc, t_ev)) {
            which.push_back(j);
        }
    }
    if (!which.empty()) {
        check(CVodeGetDky(s_.mem, t_ev, 0, s_.y), "CVodeGetDky");
    } else {
        for (int j = 0; j < sys_.contacts(); ++j) {
            if (info[static_cast<std::size_t>(3 * j)] != 0) which.push_back(j);
        }
    }
    sample_until(t_ev, true);
    update_peaks(N_VGetArrayPointer(s_.y));
    update_extremes(t_ev, N_VGetArrayPointer(s_.y));
    if (!which.empty()) toggle(t_ev, which);
    update_extremes(t_ev, N_VGetArrayPointer(s_.y));
    return t_ev;
}

// Bisection on the dense output of the last step for the closing instant of contact j (the
// closing function is negative at the step start, positive at tret). Returns the first point
// found on the positive side, to a few ulps.
double Driver::locate_missed_closing(int j, double tret) {
    double tcur = 0.0, hlast = 0.0;
    check(CVodeGetCurrentTime(s_.mem, &tcur), "CVodeGetCurrentTime");
    check(CVodeGetLastStep(s_.mem, &hlast), "CVodeGetLastStep");
    // Not before the previous return either: what lies before it is already recorded.
    double lo = std::max({tcur - hlast, t_restart_, t_done_}), hi = tret;
    check(CVodeGetDky(s_.mem, lo, 0, s_.tmp), "CVodeGetDky");
    if (sys_.closing_function(j, N_VGetArrayPointer(s_.tmp)) > 0.0) return lo;
    for (int it = 0; it < 200 && !same_time(lo, hi); ++it) {
        const double mid = 0.5 * (lo + hi);
        check(CVodeGetDky(s_.mem, mid, 0, s_.tmp), "CVodeGetDky");
        (sys_.closing_function(j, N_VGetArrayPointer(s_.tmp)) > 0.0 ? hi : lo) = mid;
    }
    return hi;
}

void Driver::toggle(double t, const std::vector<int>& which) {
    const double* y = N_VGetArrayPointer(s_.y);
    for (int j : which) {
        const auto uj = static_cast<std::size_t>(j);
        const double d = sys_.penetration(j, y);
        const double spring = 0.5 * p_.contacts[uj].stiffness * d * d;
        if (!active_[uj]) {
            ContactEpisode ep;
            ep.support = j;
            ep.t_on = t;
            ep.v_in = sys_.contact_velocity(j, y);
            ep.peak_force = std::max(sys_.force(j, y), 0.0);
            ep.peak_penetration = std::max(d, 0.0);
            open_[uj] = static_cast<int>(r_.episodes.size());
            impulse_at_onset_[uj] = y[sys_.impulse_index(j)];
            r_.episodes.push_back(ep);
            jump_ -= spring;
        } else {
            ContactEpisode& ep = r_.episodes[static_cast<std::size_t>(open_[uj])];
            ep.t_off = t;
            ep.v_out = sys_.contact_velocity(j, y);
            ep.impulse = y[sys_.impulse_index(j)] - impulse_at_onset_[uj];
            open_[uj] = -1;
            jump_ += spring;
        }
        active_[uj] = !active_[uj];
        ++r_.stats.events;
    }
    if (r_.stats.events > o_.max_events) {
        throw WorkLimitReached("solve_cvode: more than solver.max_events = " + std::to_string(o_.max_events) +
                               " contact switches before the horizon (at t = " + std::to_string(t * 1e6) +
                               " us; raise solver.max_events or shorten solver.horizon)");
    }
    // A run of switches that makes no progress in time (Zeno chatter) would never end.
    burst_ = same_time(t, last_event_t_) ? burst_ + 1 : 0;
    last_event_t_ = t;
    if (burst_ > 1000) {
        throw std::runtime_error("solve_cvode: contacts switch without progress in time (Zeno) at t = " +
                                 std::to_string(t) + " s");
    }
    sys_.set_active(active_);
    restart(t);
}

void Driver::add_counters() {
    long nst = 0, nsetups = 0;
    check(CVodeGetNumSteps(s_.mem, &nst), "CVodeGetNumSteps");
    check(CVodeGetNumLinSolvSetups(s_.mem, &nsetups), "CVodeGetNumLinSolvSetups");
    steps_done_ += nst;
    setups_done_ += nsetups;
}

// CVodeReInit resets the step counters, so they are collected first. The root directions are set
// again (event 0 wants upward crossings, events 1 and 2 downward ones). A root function exactly 0
// at the restart instant is held inactive by CVODE until it moves away from 0; one that is a
// rounding error on the wrong side moves the wrong way and is filtered by its direction.
void Driver::restart(double t) {
    add_counters();
    check(CVodeReInit(s_.mem, t, s_.y), "CVodeReInit");
    if (sys_.roots() > 0) {
        std::vector<int> dir(static_cast<std::size_t>(sys_.roots()));
        for (std::size_t i = 0; i < dir.size(); ++i) dir[i] = i % 3 == 0 ? 1 : -1;
        dir[static_cast<std::size_t>(sys_.extreme_root())] = 0;
        dir[static_cast<std::size_t>(sys_.extreme_root()) + 1] = 0;
        check(CVodeSetRootDirection(s_.mem, dir.data()), "CVodeSetRootDirection");
    }
    t_restart_ = t;
}

TransientResult Driver::run() {
    const auto t_setup = Clock::now();
    const int nc = sys_.contacts();
    for (const LoadTerm& l : p_.loads) {
        for (double b : l.time.breakpoints(0.0, p_.t_end)) stops_.push_back(b);
    }
    std::sort(stops_.begin(), stops_.end());
    stops_.erase(std::unique(stops_.begin(), stops_.end(), same_time), stops_.end());
    stops_.push_back(p_.t_end);
    samples_ = p_.output_step > 0.0
                   ? static_cast<std::size_t>(std::floor(p_.t_end / p_.output_step * (1.0 + 1e-12))) + 1
                   : 2;
    r_.history.contact_v.resize(static_cast<std::size_t>(nc));
    r_.history.contact_velocity.resize(static_cast<std::size_t>(nc));
    r_.history.contact_force.resize(static_cast<std::size_t>(nc));
    open_.assign(static_cast<std::size_t>(nc), -1);
    impulse_at_onset_.assign(static_cast<std::size_t>(nc), 0.0);
    active_.assign(static_cast<std::size_t>(nc), false);
    const Eigen::VectorXd y0 = sys_.initial_state();
    // Without active0 a contact starts closed where d > 0 and F > 0. A contact touching at t = 0
    // (d = 0 to roundoff) and moving in closes at once, as the exact solver's event search closes it:
    // CVODE holds a root function that is zero at the start inactive, and would let the beam pass
    // into the support (shared/cases/starts_in_contact.toml).
    std::vector<int> closed0;
    for (int j = 0; j < nc; ++j) {
        bool on = p_.active0.empty() ? sys_.closing_function(j, y0.data()) > 0.0
                                     : static_cast<bool>(p_.active0[static_cast<std::size_t>(j)]);
        const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
        const double scale = std::max(std::abs(e.surface), std::abs(y0[e.dof]));
        const bool touching = std::abs(sys_.penetration(j, y0.data())) <= 64.0 * kEps * scale;
        if (!on && touching && sys_.penetration_rate(j, y0.data()) > 0.0) on = true;
        if (on) closed0.push_back(j);
    }
    sys_.set_segment_end(stops_.front());
    setup();
    r_.stats.decomposition_s = seconds_since(t_setup);  // M^-1, tolerance scales, CVODE setup

    // Wall time: the whole integration, steps, root finding (inside CVODE's step, not separable),
    // restarts and sampling, is propagation_s; event_location_s stays 0.
    const auto t_run = Clock::now();
    if (!closed0.empty()) toggle(0.0, closed0);
    // Contacts closed at t = 0 are the initial state: no event, no energy jump.
    r_.stats.events = 0;
    burst_ = 0;
    jump_ = 0.0;
    r_.initial_energy = sys_.energy(y0.data(), jump_);
    sample_until(0.0, false);

    double t = 0.0;
    std::size_t seg = 0;
    for (;;) {
        const double t_stop = stops_[seg];
        if (t >= t_stop || same_time(t, t_stop)) {  // reached a stop: the end, or a load breakpoint
            sample_until(t_stop, false);
            if (seg + 1 == stops_.size()) break;
            sys_.set_segment_end(stops_[++seg]);
            restart(t);
            continue;
        }
        check(CVodeSetStopTime(s_.mem, t_stop), "CVodeSetStopTime");
        double tret = t;
        const int flag = CVode(s_.mem, t_stop, s_.y, &tret, CV_ONE_STEP);
        check(flag, "CVode");
        long nst = 0;
        check(CVodeGetNumSteps(s_.mem, &nst), "CVodeGetNumSteps");
        if (steps_done_ + nst > o_.max_steps) {
            throw WorkLimitReached("solve_cvode: more than solver.max_steps = " + std::to_string(o_.max_steps) +
                                   " steps before the horizon (at t = " + std::to_string(tret * 1e6) +
                                   " us; raise solver.max_steps, or loosen solver.rtol)");
        }
        check_run();
        if (flag == CV_ROOT_RETURN) {
            t = handle_roots(tret);
        } else {
            sample_until(tret, true);
            update_peaks(N_VGetArrayPointer(s_.y));
            update_extremes(tret, N_VGetArrayPointer(s_.y));
            t = flag == CV_TSTOP_RETURN ? t_stop : tret;
        }
        t_done_ = t;
    }
    add_counters();

    const double* y = N_VGetArrayPointer(s_.y);
    for (int j = 0; j < nc; ++j) {
        const auto uj = static_cast<std::size_t>(j);
        if (open_[uj] < 0) continue;
        ContactEpisode& ep = r_.episodes[static_cast<std::size_t>(open_[uj])];
        ep.t_off = p_.t_end;
        ep.v_out = sys_.contact_velocity(j, y);
        ep.impulse = y[sys_.impulse_index(j)] - impulse_at_onset_[uj];
        ep.closed_at_end = true;
    }
    r_.final_energy = sys_.energy(y, jump_);
    r_.t_end = p_.t_end;
    r_.stats.method = "cvode";
    r_.stats.steps = static_cast<int>(std::min<long>(steps_done_, std::numeric_limits<int>::max()));
    // For CVODE, "decompositions" counts the LU factorisations of I - gamma J (linear solver setups).
    r_.stats.decompositions = static_cast<int>(std::min<long>(setups_done_, std::numeric_limits<int>::max()));
    r_.stats.propagation_s = seconds_since(t_run);
    return std::move(r_);
}

}  // namespace

TransientResult solve_cvode(const TransientProblem& p, const CvodeOptions& o) {
    cvode_detail::validate(p);
    Driver driver(p, o);
    return driver.run();
}

}  // namespace vi
