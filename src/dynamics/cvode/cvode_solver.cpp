#include "dynamics/cvode/cvode_solver.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/cvode/cvode_conduction.hpp"
#include "dynamics/cvode/cvode_episodes.hpp"
#include "dynamics/cvode/cvode_linear_solver.hpp"
#include "dynamics/cvode/cvode_system.hpp"
#include "dynamics/cvode/fast_nvector.hpp"
#include "dynamics/cvode/free_flight.hpp"
#include "model/number_format.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

using cvode_detail::ModalSystem;
using Clock = std::chrono::steady_clock;
constexpr double kEps = std::numeric_limits<double>::epsilon();
// DOFs from which a full model's state is in the FE DOFs (nodal_state below).
constexpr int kNodalFrom = 100;


// True when a and b are the same instant up to a few ulps.
bool same_time(double a, double b) { return std::abs(a - b) <= 8.0 * kEps * std::max({std::abs(a), std::abs(b), 1e-300}); }

// Whether some element can be in a free mode (ForceElement::free_mode), so that a flight in closed
// form, which needs the modal basis, may come.
bool may_fly(const TransientProblem& p) {
    for (const ForceElementPtr& e : p.forces) {
        bool free = false;
        for (int m = 0; m < e->modes() && !free; ++m) free = e->free_mode(m).has_value();
        if (!free) return false;
    }
    return true;
}

// How many DOFs the elements act on together (a pad and its film share theirs).
int element_dofs(const TransientProblem& p) {
    std::vector<int> all;
    for (const ForceElementPtr& e : p.forces) all.insert(all.end(), e->dofs().begin(), e->dofs().end());
    std::sort(all.begin(), all.end());
    return static_cast<int>(std::unique(all.begin(), all.end()) - all.begin());
}

// Whether the full model integrates its state in the FE DOFs (a nodal basis) rather than in modal
// coordinates: from kNodalFrom DOFs up when the elements act on more than a quarter of them (an
// electrode, a film), where a right-hand side's products by the dense modal rows of those DOFs
// (O(n^2)) outweigh the sparse products and LDL^T solve with M (O(n)); point contacts read a few
// rows, and the modal state is the cheaper there. Not where a flight in closed form may come (it
// needs the modes) or K is singular (a body held by its contacts alone).
bool nodal_state(const TransientProblem& p, const CvodeOptions& o) {
    if (o.state == CvodeOptions::State::modal) return false;
    if (o.state == CvodeOptions::State::automatic &&
        (p.size() < kNodalFrom || 4 * element_dofs(p) <= p.size() || (o.free_flight && may_fly(p)))) {
        return false;
    }
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> k(p.K);
    return k.info() == Eigen::Success && (k.vectorD().array() > 0.0).all();
}

ModalBasis make_basis(const TransientProblem& p, const CvodeOptions& o) {
    if (o.reduced_modes <= 0 || o.reduced_modes >= p.size()) {
        return nodal_state(p, o) ? nodal_basis(p.size()) : full_basis(p.K, p.M);
    }
    std::vector<Eigen::VectorXd> loads;
    for (const ForceElementPtr& e : p.forces) {
        if (!o.static_corrections) break;
        for (const std::vector<double>& pattern : e->load_patterns()) {
            Eigen::VectorXd f = Eigen::VectorXd::Zero(p.size());
            for (std::size_t i = 0; i < pattern.size(); ++i) f[e->dofs()[i]] += pattern[i];
            loads.push_back(std::move(f));
        }
    }
    return reduced_basis(p.K, p.M, o.reduced_modes, loads, {p.q0, p.v0});
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
    if (code < 0) *static_cast<std::string*>(ud) = std::string(module) + "/" + function + ": " + msg;
}

// An element's refusal of a state (std::domain_error: the beam reaches an electrode) met inside a
// callback on this thread; Driver::check throws it instead of CVODE's bare failure code, so the
// caller learns what happened and can tell it from a numerical failure (dynamic pull-in does).
thread_local std::string element_refusal;

// CVODE callbacks; user_data is the ModalSystem. They never let an exception into the C library:
// one becomes an unrecoverable error (-1) and CVODE fails; an element's refusal is kept for the
// message.
template <class Call>
int guarded(Call call) {
    try {
        call();
        return 0;
    } catch (const std::domain_error& e) {
        element_refusal = e.what();
        return -1;
    } catch (...) {
        return -1;
    }
}

int rhs_fn(realtype t, N_Vector y, N_Vector ydot, void* ud) {
    return guarded([&] { static_cast<const ModalSystem*>(ud)->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)); });
}

int jac_fn(realtype t, N_Vector y, N_Vector, SUNMatrix J, void* ud, N_Vector, N_Vector, N_Vector) {
    return guarded([&] {
        cvode_detail::StructuredJacobian& j = cvode_detail::structured_content(J);
        auto tangents = std::make_shared<cvode_detail::ElementTangents>();
        const ModalSystem& sys = *static_cast<const ModalSystem*>(ud);
        if (sys.nodal()) {
            sys.fe_tangents(t, N_VGetArrayPointer(y), tangents->Fq, tangents->Fv);
        } else {
            sys.tangents(t, N_VGetArrayPointer(y), tangents->dfdq, tangents->dfdv, &tangents->modal_q, &tangents->modal_v);
        }
        j.tangents = std::move(tangents);
        j.a = 1.0;
        j.b = 0.0;
    });
}

int root_fn(realtype t, N_Vector y, realtype* g, void* ud) {
    return guarded([&] { static_cast<const ModalSystem*>(ud)->root_functions(t, N_VGetArrayPointer(y), g); });
}

class Driver {
public:
    Driver(const TransientProblem& p, const TransientOptions& o, const CvodeOptions& c)
        : p_(p), o_(o), c_(c), sys_(p, make_basis(p, c)) {}
    TransientResult run();

private:
    std::vector<int> prepare();
    void enter_initial_modes(const std::vector<int>& start);
    void integrate();
    std::optional<double> step(double t, double t_stop);
    // A flight (every element in a free mode) carried in closed form from t towards t_stop: its
    // samples, the extremes, the first switch, as step() meets them; where step() would leave the run.
    std::optional<double> fly(double t, double t_stop, const std::vector<FreeMode>& free);
    // The flight's extremes over [t, t_ev] after the first onset (update_extremes' between the ends).
    void flight_extremes(double t_ev);
    void finish();
    void check(int flag, const char* what) const;
    void setup();
    [[nodiscard]] double sample_time(std::size_t k) const;
    void sample_until(double t_lim, bool interpolate);
    void record(double t, const double* y);
    double handle_roots(double tret);
    [[nodiscard]] bool contact_closed() const;  // some contact element is in its contact mode
    // Whether some element is in a terminal mode (ForceElement::ends_run); if so, records it as what
    // ended the run at t.
    bool ended_by_element(double t);
    double locate_missed_switch(int e, double tret);
    // The contacts' conduction at a return of CVODE at t, located on the last step's dense output.
    void advance_conduction(double t);
    // The open episodes' contact energy up to a return of CVODE at t, on the last step's dense output.
    void advance_dissipation(double t);
    // The state at a time inside the last step, in s_.tmp.
    [[nodiscard]] const double* dense_state(double t);
    void toggle(double t, const std::vector<int>& which);
    void restart(double t);
    void add_counters();
    // What a time limit reached during the integration reports (model/run_control.hpp).
    [[nodiscard]] std::string progress() const;
    [[nodiscard]] std::string step_limit_message(double t) const;
    // Whether the basis's highest vector is undamped (at most 1e-3 of critical damping).
    [[nodiscard]] bool top_undamped() const;
    [[nodiscard]] double top_frequency() const;  // the basis's highest frequency [rad/s]
    // Ends the run early when its pace of steps, sustained over the last windows, cannot reach the
    // horizon within solver.max_steps (see the definition).
    void check_pace(double t, long steps);
    [[nodiscard]] std::string undamped_top_advice() const;

    const TransientProblem& p_;
    TransientOptions o_;
    CvodeOptions c_;
    ModalSystem sys_;
    Sundials s_;
    std::string cvode_message_;
    double t_final_ = p_.t_end;          // the horizon, or the first contact with stop_at_first_contact
    int close_root_restarts_ = 0;  // restarts after CVODE's "root found at and very near t"
    TransientResult r_;
    Eigen::VectorXd y0_;                 // the state at t = 0
    std::vector<double> stops_;          // element time stops in (0, t_end), then t_end
    std::size_t samples_ = 0, next_sample_ = 0;
    std::vector<int> modes_;             // each element's mode
    cvode_detail::EpisodeRecorder episodes_{sys_, r_};
    cvode_detail::ConductionRecorder conduction_{sys_, r_};
    // Flights in closed form (c_.free_flight and a basis it can take), and what their searches may
    // spend: solver.max_steps evaluations, as the exact solver's.
    cvode_detail::FreeFlight flight_{sys_};
    long flight_budget_ = 0;
    // Energy that appears or vanishes in an element at a switch: a Kelvin-Voigt contact opening with
    // d > 0 (the damped case: F = 0 before d = 0) drops 1/2 Kc d^2 from its stored energy. A massless
    // element left alone relaxes through its damper, which dissipates exactly that, so it is booked
    // as dissipated; a switch that stores energy (a contact closing with d > 0) takes it back.
    double jump_ = 0.0;
    long steps_done_ = 0, setups_done_ = 0;
    double t_restart_ = 0.0, last_event_t_ = -1.0;
    double t_done_ = 0.0;                // time of the last return of CVODE (all before is recorded)
    double dissipation_t_ = 0.0;         // the episodes' contact energy is integrated up to here [s]
    int burst_ = 0;
    int stalled_roots_ = 0;              // root returns in a row at one instant that switched nothing
    bool paced_ = false;                 // check_pace applies (set in prepare)
    int windows_needed_ = 3;             // windows in a row over the budget that end the run
    int windows_over_ = 0;               // windows in a row whose pace needs more than the budget
    double least_need_ = 0.0;            // the fewest steps one of those windows' paces needs
    long pace_steps_ = 0;                // steps and time at the start of the pace window
    double pace_t_ = 0.0;
};

void Driver::check(int flag, const char* what) const {
    if (flag >= 0) return;
    char* name = CVodeGetReturnFlagName(flag);
    std::string msg = std::string("solve_cvode: ") + what + " failed (" + (name ? name : "?") + ")";
    std::free(name);
    if (!cvode_message_.empty()) msg += ": " + cvode_message_;
    if (!element_refusal.empty()) {
        std::string refusal;
        refusal.swap(element_refusal);
        throw std::domain_error(msg + "; " + refusal);
    }
    throw std::runtime_error(msg);
}

void Driver::setup() {
    const int N = sys_.size();
    if (SUNContext_Create(nullptr, &s_.ctx) != 0) throw std::runtime_error("solve_cvode: SUNContext_Create failed");
    s_.y = cvode_detail::new_fast_vector(N, s_.ctx);
    s_.tmp = cvode_detail::new_fast_vector(N, s_.ctx);
    s_.atol = cvode_detail::new_fast_vector(N, s_.ctx);
    if (!s_.y || !s_.tmp || !s_.atol) throw std::runtime_error("solve_cvode: out of memory");
    s_.A = cvode_detail::structured_matrix(sys_, s_.ctx);
    s_.LS = cvode_detail::structured_solver(sys_, s_.ctx);
    s_.mem = CVodeCreate(CV_BDF, s_.ctx);
    if (!s_.mem) throw std::runtime_error("solve_cvode: CVODE setup failed");
    check(CVodeSetErrHandlerFn(s_.mem, error_fn, &cvode_message_), "CVodeSetErrHandlerFn");

    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(s_.y), N) = sys_.initial_state();
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(s_.atol), N) = sys_.absolute_tolerances(c_.rtol * c_.atol_ratio);
    check(CVodeInit(s_.mem, rhs_fn, 0.0, s_.y), "CVodeInit");
    check(CVodeSVtolerances(s_.mem, c_.rtol, s_.atol), "CVodeSVtolerances");
    check(CVodeSetUserData(s_.mem, &sys_), "CVodeSetUserData");
    check(CVodeSetLinearSolver(s_.mem, s_.LS, s_.A), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(s_.mem, jac_fn), "CVodeSetJacFn");
    check(CVodeSetMaxNumSteps(s_.mem, std::min<long>(o_.max_steps, std::numeric_limits<int>::max())), "CVodeSetMaxNumSteps");
    check(CVodeSetMaxHnilWarns(s_.mem, -1), "CVodeSetMaxHnilWarns");
    check(CVodeRootInit(s_.mem, sys_.roots(), root_fn), "CVodeRootInit");
    check(CVodeSetNoInactiveRootWarn(s_.mem), "CVodeSetNoInactiveRootWarn");
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
    const long index = static_cast<long>(h.t.size());
    if (is_field_sample(index, o_.field_every, static_cast<long>(samples_))) {
        const Eigen::Map<const Eigen::VectorXd> state(y, sys_.basis_size());
        const Eigen::VectorXd q = sys_.nodal() ? Eigen::VectorXd(state) : Eigen::VectorXd(sys_.basis().phi * state);
        h.field_sample.push_back(static_cast<std::size_t>(index));
        h.field_q.emplace_back(q.data(), q.data() + q.size());
    }
    h.t.push_back(t);
    h.watched_v.push_back(sys_.watched(y));
    h.watched_velocity.push_back(sys_.watched_velocity(y));
    for (std::size_t j = 0; j < sys_.contacts().size(); ++j) {
        const int e = sys_.contacts()[j];
        const ContactReading c = sys_.reading(e, t, y);
        h.contact_v[j].push_back(sys_.contact_displacement(static_cast<int>(j), y));
        h.contact_velocity[j].push_back(c.point_velocity);
        h.contact_force[j].push_back(modes_[static_cast<std::size_t>(e)] == sys_.element(e).contact_mode() ? c.force : 0.0);
    }
    if (o_.energy) h.energy.push_back(sys_.energy(t, y, jump_));
}

double Driver::handle_roots(double tret) {
    std::vector<int> info(static_cast<std::size_t>(sys_.roots()), 0);
    check(CVodeGetRootInfo(s_.mem, info.data()), "CVodeGetRootInfo");
    const double* y = N_VGetArrayPointer(s_.y);
    double t_ev = tret;
    std::vector<int> which;
    // Guard: an element whose watch function has a root (for a contact: a maximum of d) and whose
    // switching function is positive there switched earlier in this step without CVODE seeing the
    // switching function change sign at the step ends (d up through 0 and back within one step).
    for (int e = 0; e < sys_.elements(); ++e) {
        const ForceElement& el = sys_.element(e);
        if (sys_.switch_root(e) < 0 || el.watch_count() == 0) continue;
        if (info[static_cast<std::size_t>(sys_.switch_root(e))] != 0) continue;
        bool watched = false;
        for (int k = 0; k < el.watch_count(); ++k) watched = watched || info[static_cast<std::size_t>(sys_.watch_root(e) + k)] != 0;
        if (!watched || sys_.switching_function(e, modes_[static_cast<std::size_t>(e)], tret, y) <= 0.0) continue;
        const double tc = locate_missed_switch(e, tret);
        if (which.empty() || tc < t_ev) {
            which = {e};
            t_ev = tc;
        } else if (same_time(tc, t_ev)) {
            which.push_back(e);
        }
    }
    if (!which.empty()) {
        check(CVodeGetDky(s_.mem, t_ev, 0, s_.y), "CVodeGetDky");
    } else {
        for (int e = 0; e < sys_.elements(); ++e) {
            if (sys_.switch_root(e) >= 0 && info[static_cast<std::size_t>(sys_.switch_root(e))] != 0) which.push_back(e);
        }
    }
    sample_until(t_ev, true);
    advance_dissipation(t_ev);
    episodes_.update_peaks(t_ev, N_VGetArrayPointer(s_.y));
    episodes_.update_extremes(t_ev, N_VGetArrayPointer(s_.y), modes_);
    advance_conduction(t_ev);
    if (!which.empty()) {
        toggle(t_ev, which);
        conduction_.switched(t_ev, N_VGetArrayPointer(s_.y), modes_);
    }
    episodes_.update_extremes(t_ev, N_VGetArrayPointer(s_.y), modes_);
    return t_ev;
}

const double* Driver::dense_state(double t) {
    check(CVodeGetDky(s_.mem, t, 0, s_.tmp), "CVodeGetDky");
    return N_VGetArrayPointer(s_.tmp);
}

void Driver::advance_conduction(double t) {
    if (!conduction_.active()) return;
    double tcur = 0.0, hlast = 0.0;
    check(CVodeGetCurrentTime(s_.mem, &tcur), "CVodeGetCurrentTime");
    check(CVodeGetLastStep(s_.mem, &hlast), "CVodeGetLastStep");
    conduction_.advance(t, N_VGetArrayPointer(s_.y), modes_, std::max(tcur - hlast, t_restart_),
                        [this](double ts) { return dense_state(ts); });
}

void Driver::advance_dissipation(double t) {
    if (episodes_.any_open() && t > dissipation_t_) {
        double tcur = 0.0, hlast = 0.0;
        check(CVodeGetCurrentTime(s_.mem, &tcur), "CVodeGetCurrentTime");
        check(CVodeGetLastStep(s_.mem, &hlast), "CVodeGetLastStep");
        const double lo = std::max({dissipation_t_, tcur - hlast, t_restart_});
        episodes_.add_dissipation(lo, t, modes_, [this](double ts) { return dense_state(ts); });
    }
    dissipation_t_ = std::max(dissipation_t_, t);
}

// Bisection on the dense output of the last step for the instant element e's switching function
// turned positive (negative at the step start, positive at tret). Returns the first point found on
// the positive side, to a few ulps.
double Driver::locate_missed_switch(int e, double tret) {
    double tcur = 0.0, hlast = 0.0;
    check(CVodeGetCurrentTime(s_.mem, &tcur), "CVodeGetCurrentTime");
    check(CVodeGetLastStep(s_.mem, &hlast), "CVodeGetLastStep");
    // Not before the previous return either: what lies before it is already recorded.
    double lo = std::max({tcur - hlast, t_restart_, t_done_}), hi = tret;
    const int mode = modes_[static_cast<std::size_t>(e)];
    check(CVodeGetDky(s_.mem, lo, 0, s_.tmp), "CVodeGetDky");
    if (sys_.switching_function(e, mode, lo, N_VGetArrayPointer(s_.tmp)) > 0.0) return lo;
    for (int it = 0; it < 200 && !same_time(lo, hi); ++it) {
        const double mid = 0.5 * (lo + hi);
        check(CVodeGetDky(s_.mem, mid, 0, s_.tmp), "CVodeGetDky");
        (sys_.switching_function(e, mode, mid, N_VGetArrayPointer(s_.tmp)) > 0.0 ? hi : lo) = mid;
    }
    return hi;
}

void Driver::toggle(double t, const std::vector<int>& which) {
    const double* y = N_VGetArrayPointer(s_.y);
    for (int e : which) {
        const std::size_t ue = static_cast<std::size_t>(e);
        const ForceElement& el = sys_.element(e);
        const int from = modes_[ue];
        const int to = el.mode_after_switch(from);
        jump_ -= sys_.stored_energy(e, to, t, y) - sys_.stored_energy(e, from, t, y);
        episodes_.on_switch(e, from, to, t, y);
        modes_[ue] = to;
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
        throw std::runtime_error("solve_cvode: " + sys_.element(which.front()).name() +
                                 " switches without progress in time (Zeno) at t = " + std::to_string(t * 1e6) + " us");
    }
    sys_.set_modes(modes_);
    restart(t);
}

bool Driver::contact_closed() const {
    for (int e : sys_.contacts()) {
        if (modes_[static_cast<std::size_t>(e)] == sys_.element(e).contact_mode()) return true;
    }
    return false;
}

bool Driver::ended_by_element(double t) {
    for (int e = 0; e < sys_.elements(); ++e) {
        if (!sys_.element(e).ends_run(modes_[static_cast<std::size_t>(e)])) continue;
        r_.ended_by = RunEndEvent{e, sys_.element(e).name(), t, sys_.run_end(e, t, N_VGetArrayPointer(s_.y))};
        return true;
    }
    return false;
}

void Driver::add_counters() {
    long nst = 0, nsetups = 0;
    check(CVodeGetNumSteps(s_.mem, &nst), "CVodeGetNumSteps");
    check(CVodeGetNumLinSolvSetups(s_.mem, &nsetups), "CVodeGetNumLinSolvSetups");
    steps_done_ += nst;
    setups_done_ += nsetups;
}

// CVodeReInit resets the step counters, so they are collected first; it also forces a new Jacobian
// (the elements' tangents change with their modes). A root function exactly 0 at the restart
// instant is held inactive by CVODE until it moves away from 0; one that is a rounding error on the
// wrong side moves the wrong way and is filtered by its direction.
void Driver::restart(double t) {
    add_counters();
    check(CVodeReInit(s_.mem, t, s_.y), "CVodeReInit");
    std::vector<int> dir = sys_.root_directions();
    check(CVodeSetRootDirection(s_.mem, dir.data()), "CVodeSetRootDirection");
    t_restart_ = t;
}

// The stops, the sample count, the history's columns, the initial state, CVODE set up; returns each
// element's mode at t = 0.
std::vector<int> Driver::prepare() {
    const std::size_t nc = sys_.contacts().size();
    stops_ = time_stops(p_.forces, 0.0, p_.t_end);
    stops_.push_back(p_.t_end);
    samples_ = p_.output_step > 0.0 ? static_cast<std::size_t>(std::floor(p_.t_end / p_.output_step * (1.0 + 1e-12))) + 1
                                    : 2;
    r_.history.contact_v.resize(nc);
    r_.history.contact_velocity.resize(nc);
    r_.history.contact_force.resize(nc);
    y0_ = sys_.initial_state();
    const std::vector<int> start = sys_.initial_modes(y0_.data());
    // A run that ends at its first contact may end long before the horizon: its pace says nothing.
    paced_ = !c_.stop_at_first_contact;
    flight_budget_ = o_.max_steps;
    windows_needed_ = top_undamped() ? 1 : 3;
    modes_.assign(start.size(), 0);
    sys_.set_modes(modes_);
    sys_.set_segment_end(stops_.front());
    setup();
    return start;
}

// Elements in another mode at t = 0 are the initial state: they switch at once, counted as no event
// and with no energy jump.
void Driver::enter_initial_modes(const std::vector<int>& start) {
    std::vector<int> switched;
    for (std::size_t e = 0; e < start.size(); ++e) {
        if (start[e] != 0) switched.push_back(static_cast<int>(e));
    }
    if (!switched.empty()) {
        for (int e : switched) {
            // mode_after_switch toggles two-mode elements; an element with more modes is set directly.
            if (sys_.element(e).modes() > 2) modes_[static_cast<std::size_t>(e)] = start[static_cast<std::size_t>(e)];
        }
        std::vector<int> toggled;
        for (int e : switched) {
            if (sys_.element(e).modes() <= 2) toggled.push_back(e);
        }
        if (!toggled.empty()) toggle(0.0, toggled);
        sys_.set_modes(modes_);
    }
    r_.stats.events = 0;
    burst_ = 0;
    jump_ = 0.0;
}

// One return of CVODE towards t_stop from t (a step, a root, the stop); returns where it left the
// run, or nullopt when the run ends there (stop_at_first_contact).
std::optional<double> Driver::step(double t, double t_stop) {
    check(CVodeSetStopTime(s_.mem, t_stop), "CVodeSetStopTime");
    double tret = t;
    const int flag = CVode(s_.mem, t_stop, s_.y, &tret, CV_ONE_STEP);
    // A root function that stays exactly 0 just after a root it returned (a velocity at the noise
    // level of a stiff start, e.g. a distributed force switched on at t = 0) makes CVODE refuse to go
    // on; a restart there holds that function inactive until it moves away from 0.
    if (flag == CV_ILL_INPUT && cvode_message_.find("very near") != std::string::npos && close_root_restarts_ < 1000) {
        ++close_root_restarts_;
        cvode_message_.clear();
        restart(t);
        return t;
    }
    check(flag, "CVode");
    long nst = 0;
    check(CVodeGetNumSteps(s_.mem, &nst), "CVodeGetNumSteps");
    if (steps_done_ + nst > o_.max_steps) throw WorkLimitReached(step_limit_message(tret));
    check_pace(tret, steps_done_ + nst);
    check_run();
    if (o_.progress) o_.progress(tret);
    if (flag == CV_ROOT_RETURN) {
        const int events_before = r_.stats.events;
        t = handle_roots(tret);
        // Watch functions at the rounding level (a velocity of 1e-23 m/s just after a start at rest)
        // can make CVODE return the same root again and again without stepping. A restart there
        // forgets the step history and holds a function that is exactly 0 inactive.
        if (r_.stats.events == events_before && same_time(t, t_done_)) {
            if (++stalled_roots_ > 100) {
                throw std::runtime_error("solve_cvode: root finding makes no progress in time at t = " +
                                         std::to_string(t * 1e6) +
                                         " us (a watch function stays at the rounding level; tighten solver.rtol)");
            }
            restart(t);
        } else {
            stalled_roots_ = 0;
        }
        if (ended_by_element(t) || (c_.stop_at_first_contact && contact_closed())) {
            sample_until(t, false);
            t_final_ = t;
            return std::nullopt;
        }
    } else {
        sample_until(tret, true);
        advance_dissipation(tret);
        episodes_.update_peaks(tret, N_VGetArrayPointer(s_.y));
        episodes_.update_extremes(tret, N_VGetArrayPointer(s_.y), modes_);
        advance_conduction(tret);
        t = flag == CV_TSTOP_RETURN ? t_stop : tret;
    }
    t_done_ = t;
    return t;
}

std::optional<double> Driver::fly(double t, double t_stop, const std::vector<FreeMode>& free) {
    double* y = N_VGetArrayPointer(s_.y);
    flight_.start(t, y);
    double t_ev = t_stop;
    std::vector<int> which;
    for (int e = 0; e < sys_.elements(); ++e) {
        const std::optional<double> ts = flight_.first_switch(e, free[static_cast<std::size_t>(e)], t_ev, &flight_budget_);
        if (!ts) continue;
        if (!which.empty() && same_time(*ts, t_ev)) {
            which.push_back(e);
        } else {
            which = {e};
            t_ev = *ts;
        }
    }
    ++r_.stats.free_flights;
    if (!r_.episodes.empty()) {
        episodes_.update_extremes(t, y, modes_);
        flight_extremes(t_ev);
    }
    for (long k = 0; next_sample_ < samples_ && sample_time(next_sample_) < t_ev && !same_time(sample_time(next_sample_), t_ev);
         ++next_sample_, ++k) {
        if ((k & 1023) == 1023) check_run();
        const double ts = sample_time(next_sample_);
        flight_.state(ts, N_VGetArrayPointer(s_.tmp));
        record(ts, N_VGetArrayPointer(s_.tmp));
    }
    flight_.state(t_ev, y);
    sample_until(t_ev, false);
    check_run();
    if (o_.progress) o_.progress(t_ev);
    dissipation_t_ = std::max(dissipation_t_, t_ev);
    episodes_.update_extremes(t_ev, y, modes_);
    t_done_ = t_ev;
    if (which.empty()) return t_ev;
    toggle(t_ev, which);
    conduction_.switched(t_ev, y, modes_);
    episodes_.update_extremes(t_ev, y, modes_);
    if (ended_by_element(t_ev) || (c_.stop_at_first_contact && contact_closed())) {
        t_final_ = t_ev;
        return std::nullopt;
    }
    return t_ev;
}

void Driver::flight_extremes(double t_ev) {
    Extremes& ex = r_.extremes;
    const SignalMaximum top = flight_.maximum(sys_.watched_row(), t_ev, ex.watched_max, &flight_budget_);
    if (top.tau >= 0.0) {
        ex.watched_max = top.value;
        ex.watched_max_t = top.tau;
    }
    if (!sys_.contacts().empty()) {
        const SignalMaximum c = flight_.maximum(sys_.contact_row(0), t_ev, ex.contact_max, &flight_budget_);
        if (c.tau >= 0.0) ex.contact_max = c.value;
    }
}

// solver.max_steps reached at t: what raises it, and why the steps were many when the model keeps
// undamped modes far above the physics (every mode of the mesh, at most 1e-3 of critical damping
// at the top: CVODE follows them at every step once an impact or a step of voltage excites them).
std::string Driver::step_limit_message(double t) const {
    std::string m = "solve_cvode: more than solver.max_steps = " + std::to_string(o_.max_steps) +
                    " steps before the horizon (at t = " + significant(t, 6) + " s of " + significant(p_.t_end, 6) + " s";
    if (top_undamped()) return m + "): " + undamped_top_advice();
    return m + "; raise solver.max_steps, shorten solver.horizon, or loosen solver.rtol)";
}

double Driver::top_frequency() const {
    if (sys_.nodal()) return sys_.nodal()->top_frequency();
    const ModalBasis& b = sys_.basis();
    return b.omega.size() > 0 ? b.omega[b.omega.size() - 1] : 0.0;
}

bool Driver::top_undamped() const {
    const double w = top_frequency();
    return w > 0.0 && p_.alpha + p_.beta * w * w <= 2e-3 * w;
}

std::string Driver::undamped_top_advice() const {
    const ModalBasis& b = sys_.basis();
    const std::string hz = significant(top_frequency() / (2.0 * std::numbers::pi), 3) + " Hz";
    if (b.full) {
        return "the full model without damping keeps its highest mode (" + hz +
               ") ringing and CVODE follows it; set solver.reduced_modes (e.g. 16) or add [damping], or raise "
               "solver.max_steps";
    }
    return "the reduced model without damping keeps its highest vector (" + hz +
           ") ringing and CVODE follows it; add [damping], lower solver.reduced_modes, or raise solver.max_steps";
}

// A run that meets solver.max_steps spends the whole budget first (the switch example without
// [damping] on the full model: 4.2 million steps over its 50 us, about 17 s of CPU for the default
// million). Its pace of steps per unit of simulated time, carried from the last window of
// max(1000, max_steps / 20) steps to the horizon, says that early: the run ends there with the steps
// it needs and the same advice. A burst (an impact's chatter) is no pace: three windows in a row
// must each need more than the budget, and half the budget must be spent: a pace can still fall
// (the capacitive stiction example with a changed drive: 150 000 steps at a pace of 3 million over
// its horizon, then an answer in 1.7 s of CPU), and a run that answers within half the budget is
// never ended by it. Without damping in the basis's highest vector one window, once a tenth of the
// budget is spent, does: once an impact or a step of force has set that vector ringing it keeps its
// amplitude for the rest of the run, and CVODE follows it at a steady pace (that example: 119 000
// steps to 2 us, 418 000 to 5 us, 841 000 to 10 us; a switch under a stiff air film at 10 MPa spent
// 21 s of CPU on half the budget). Not for a run that ends at its first contact, which may come
// long before the horizon.
void Driver::check_pace(double t, long steps) {
    const long window = std::max<long>(1000, o_.max_steps / 20);
    if (!paced_ || steps - pace_steps_ < window) return;
    const double span = t - pace_t_;
    const double pace = span > 0.0 ? static_cast<double>(steps - pace_steps_) / span
                                   : std::numeric_limits<double>::infinity();
    const double need = static_cast<double>(steps) + pace * (p_.t_end - t);
    const long last = steps - pace_steps_;
    pace_steps_ = steps;
    pace_t_ = t;
    // A quarter above the budget: a pace carried to the horizon is good to some percent (the
    // reduced-order example with ratios of 1e-6 answered in 990 000 steps of a million, where its
    // pace said 1.0 million).
    const bool over = need > 1.25 * static_cast<double>(o_.max_steps);
    least_need_ = over && windows_over_ > 0 ? std::min(least_need_, need) : need;
    windows_over_ = over ? windows_over_ + 1 : 0;
    // A ringing undamped top vector keeps its pace, so a tenth of the budget is enough to know it.
    const long spent = windows_needed_ == 1 ? o_.max_steps / 10 : o_.max_steps / 2;
    if (windows_over_ < windows_needed_ || steps < spent) return;
    const std::string m = "solve_cvode: at the pace of its last " + std::to_string(windows_needed_) +
                          (windows_needed_ == 1 ? " window" : " windows") + " of " + std::to_string(last) + " steps (" +
                          significant(pace * 1e-6, 3) + " per us of simulated time in the last, at t = " + significant(t, 6) +
                          " s of " + significant(p_.t_end, 6) + " s) the horizon needs about " + significant(least_need_, 2) +
                          " steps, more than solver.max_steps = " + std::to_string(o_.max_steps);
    if (top_undamped()) throw WorkLimitReached(m + ": " + undamped_top_advice());
    throw WorkLimitReached(m + "; raise solver.max_steps, shorten solver.horizon, or loosen solver.rtol");
}

// The time reached, CVODE's steps so far and its last step, and the closest contact gap at that
// time (negative: a penetration): computed only when a time limit is reached.
std::string Driver::progress() const {
    std::string out = "CVODE had reached t = " + significant(t_done_, 6) + " s of " + significant(p_.t_end, 6) + " s";
    long steps = 0;
    double h = 0.0;
    if (s_.mem != nullptr && CVodeGetNumSteps(s_.mem, &steps) == CV_SUCCESS) {
        out += " in " + std::to_string(steps_done_ + steps) + " steps";
    }
    if (s_.mem != nullptr && CVodeGetLastStep(s_.mem, &h) == CV_SUCCESS && h > 0.0) {
        out += "; last step " + significant(h, 3) + " s";
    }
    double gap = std::numeric_limits<double>::infinity();
    for (const int e : sys_.contacts()) gap = std::min(gap, -sys_.reading(e, t_done_, N_VGetArrayPointer(s_.y)).penetration);
    if (std::isfinite(gap)) out += "; closest contact gap " + significant(gap, 3) + " m (negative: penetration)";
    return out;
}

// From t = 0 to the horizon, stop by stop (element time stops, each a restart), or to the
// element that ends the run.
void Driver::integrate() {
    double t = 0.0;
    std::size_t seg = 0;
    const ProgressNote note([this] { return progress(); });
    if (ended_by_element(0.0)) t_final_ = 0.0;
    while (!r_.ended_by) {
        const double t_stop = stops_[seg];
        if (t >= t_stop || same_time(t, t_stop)) {  // reached a stop: the end, a step or a corner
            sample_until(t_stop, false);
            if (seg + 1 == stops_.size()) return;
            // The step history describes the right-hand side before the stop: carried across a
            // corner, CVODE's error test failed there without end at rtol 1e-12 (a ramp from rest).
            sys_.set_segment_end(stops_[++seg]);
            restart(t);
            continue;
        }
        std::optional<std::vector<FreeMode>> free;
        if (c_.free_flight && flight_.usable()) free = flight_.free_modes(modes_);
        const std::optional<double> next = free ? fly(t, t_stop, *free) : step(t, t_stop);
        if (!next) return;
        t = *next;
    }
}

// Episodes open at the end, the final ledger, the statistics.
void Driver::finish() {
    add_counters();
    const double* y = N_VGetArrayPointer(s_.y);
    episodes_.close_at_end(t_final_, y);
    conduction_.finish(t_final_, y, modes_);
    r_.final_energy = sys_.energy(t_final_, y, jump_);
    r_.t_end = t_final_;
    r_.stats.method = "cvode";
    r_.stats.basis_vectors = sys_.basis_size();
    r_.stats.basis_modes = sys_.basis().modes;
    r_.stats.nodal_state = sys_.nodal() != nullptr;
    r_.stats.initial_projection_error = sys_.initial_projection_error();
    r_.stats.steps = static_cast<int>(std::min<long>(steps_done_, std::numeric_limits<int>::max()));
    // For CVODE, "decompositions" counts the factorisations of the Newton matrix (linear solver setups).
    r_.stats.decompositions = static_cast<int>(std::min<long>(setups_done_, std::numeric_limits<int>::max()));
}

TransientResult Driver::run() {
    const auto t_setup = Clock::now();
    const std::vector<int> start = prepare();
    r_.stats.decomposition_s = seconds_since(t_setup);  // basis, tolerance scales, CVODE setup

    // Wall time: the whole integration, steps, root finding (inside CVODE's step, not separable),
    // restarts and sampling, is propagation_s; event_location_s stays 0.
    const auto t_run = Clock::now();
    enter_initial_modes(start);
    conduction_.start(y0_.data(), modes_);
    r_.initial_energy = sys_.energy(0.0, y0_.data(), jump_);
    sample_until(0.0, false);
    integrate();
    finish();
    r_.stats.propagation_s = seconds_since(t_run);
    return std::move(r_);
}

}  // namespace

TransientResult solve_cvode(const TransientProblem& p, const TransientOptions& o, const CvodeOptions& c) {
    cvode_detail::validate(p);
    element_refusal.clear();
    Driver driver(p, o, c);
    return driver.run();
}

}  // namespace vi
