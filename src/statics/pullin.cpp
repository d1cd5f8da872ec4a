#include "statics/pullin.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "forces/force_assembly.hpp"
#include "statics/bordered_solver.hpp"
#include "problem/electrode_elements.hpp"
#include "problem/beam_model.hpp"
#include "statics/static_solution.hpp"
#include "modal/eigen_solver.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"

// The unknowns are the bending DOFs q and lambda = V^2 (every electrode's force is V^2 times its
// force at 1 V). Newton's method solves K q = F_contacts(q) + lambda F_e(q) together with
// r . q = tau, r the mean travel over electrodes[0]: the bordered matrix stays regular at the fold,
// where dlambda/dtau = 0, so stepping tau traces the branch through pull-in (docs/electrostatics.md §4).

namespace vi {
namespace {

using Index = Eigen::Index;
using Triplet = Eigen::Triplet<double>;
using PadPtr = std::shared_ptr<const ElectrostaticPad>;

using Model = PullinModel;

struct State {
    double tau = 0.0;
    double lambda = 0.0;
    Eigen::VectorXd q;
    std::vector<int> modes;  // per contact
};

// The model's elements are evaluated one at a time through one assembler per thread: an
// electrode's tangent is a dense block over the DOFs it faces (10^4 entries at m = 50), and buffers
// kept between Newton steps spare an allocation and its page faults at every one.
ElementAssembler& assembler() {
    thread_local ElementAssembler a;
    return a;
}

// Adds factor x the element's static force to f (and the force itself to unscaled if given) and
// factor x its stiffness to jt (the Jacobian of K q - F). Returns false when the element cannot be
// evaluated there (the beam past an electrode).
bool add_element(const ForceElement& e, int mode, const Eigen::VectorXd& q, double factor, Eigen::VectorXd& f,
                 std::vector<Triplet>* jt, Eigen::VectorXd* unscaled = nullptr) {
    ElementAssembler& a = assembler();
    a.gather(e, q);
    try {
        a.force(mode);
        if (jt) a.tangent(mode);
    } catch (const std::domain_error&) {
        return false;
    }
    a.scatter_force(factor, f);
    if (unscaled) a.scatter_force(1.0, *unscaled);
    if (jt) a.scatter_stiffness(factor, *jt);
    return true;
}

// F_contacts + lambda F_e at the state, the tangent A = K - dF/dq and F_e, the electrodes' force
// at 1 V; false where undefined.
bool evaluate(const Model& m, const State& s, Eigen::VectorXd& force, SparseMatrix* tangent,
              Eigen::VectorXd* pad_force = nullptr) {
    const Index n = m.K.rows();
    force = Eigen::VectorXd::Zero(n);
    if (pad_force) *pad_force = Eigen::VectorXd::Zero(n);
    std::vector<Triplet> jt;
    std::vector<Triplet>* pj = tangent ? &jt : nullptr;
    for (std::size_t k = 0; k < m.contacts.size(); ++k) {
        if (!add_element(*m.contacts[k], s.modes[k], s.q, 1.0, force, pj)) return false;
    }
    for (const ForceElementPtr& e : m.structural) {
        if (!add_element(*e, 0, s.q, 1.0, force, pj)) return false;
    }
    for (const PadPtr& p : m.pads) {
        if (!add_element(*p, 0, s.q, s.lambda, force, pj, pad_force)) return false;
    }
    if (tangent) *tangent = with_stiffness(m.K, jt);
    return true;
}

// Newton's method at travel tau from the guess s (modes re-decided after every step unless fixed).
// Returns false when it does not converge within the model's iteration bound.
bool solve_at(const Model& m, double tau, State& s, bool fix_modes, int& iterations, BorderedSolver& ls) {
    s.tau = tau;
    const double q_scale = 1e-3 * m.air_gap;
    double previous_step = std::numeric_limits<double>::infinity();
    for (int it = 0; it < m.max_iterations; ++it) {
        check_run();
        ++iterations;
        Eigen::VectorXd force, fe;
        SparseMatrix a;
        if (!evaluate(m, s, force, &a, &fe)) return false;
        const Eigen::VectorXd rhs = -(m.K * s.q - force);
        if (!ls.factorize(std::move(a), -fe, m.row)) return false;
        Eigen::VectorXd dq;
        double dlambda = 0.0;
        if (!ls.solve(rhs, tau - m.row.dot(s.q), dq, dlambda)) return false;
        s.q += dq;
        s.lambda += dlambda;
        bool changed = false;
        if (!fix_modes) {
            for (std::size_t k = 0; k < m.contacts.size(); ++k) {
                const int mode = m.contacts[k]->static_mode(assembler().gather(*m.contacts[k], s.q));
                changed = changed || mode != s.modes[k];
                s.modes[k] = mode;
            }
        }
        // Converged once the state is within 1e-9 of the solution (K's condition times eps is itself
        // about 1e-9 at m = 50): a step that small, or a step in Newton's quadratic regime (small,
        // and contracting fast) after which the error left, about step^3 / previous^2, is that small.
        const double q_size = std::max(s.q.cwiseAbs().maxCoeff(), q_scale);
        const double step =
            std::max(dq.cwiseAbs().maxCoeff() / q_size, std::abs(dlambda) / (std::abs(s.lambda) + 1e-300));
        const bool quadratic = step <= 1e-5 && step <= 1e-2 * previous_step &&
                               step * step * step <= 1e-9 * previous_step * previous_step;
        if (!changed && (step <= 1e-9 || quadratic)) return true;
        previous_step = changed ? std::numeric_limits<double>::infinity() : step;
    }
    return false;
}

// d lambda / d tau at a converged state: the bordered system with right-hand side (0, 1).
double lambda_slope(const Model& m, const State& s, BorderedSolver& ls) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXd force, fe;
    SparseMatrix a;
    if (!evaluate(m, s, force, &a, &fe)) return nan;
    const Index n = a.rows();
    if (!ls.factorize(std::move(a), -fe, m.row)) return nan;
    Eigen::VectorXd dq;
    double slope = nan;
    return ls.solve(Eigen::VectorXd::Zero(n), 1.0, dq, slope) ? slope : nan;
}

bool is_stable(const Model& m, const State& s, BorderedSolver& ls) {
    Eigen::VectorXd force;
    SparseMatrix a;
    if (!evaluate(m, s, force, &a)) return false;
    return ls.positive_definite(a);
}

PullinPoint describe(const Model& m, const State& s, BorderedSolver& ls) {
    PullinPoint p;
    p.travel = s.tau;
    p.voltage = std::sqrt(std::max(s.lambda, 0.0));
    for (const PadPtr& pad : m.pads) p.capacitance += pad->capacitance(assembler().gather(*pad, s.q).q);
    p.watched_travel = m.watched >= 0 ? m.sign * s.q[m.watched] : 0.0;
    for (std::size_t k = 0; k < m.contacts.size(); ++k) {
        if (s.modes[k] != m.contacts[k]->contact_mode()) continue;
        p.contact = true;
        p.contact_force += m.contacts[k]->contact_reading(assembler().gather(*m.contacts[k], s.q)).force;
    }
    p.stable = is_stable(m, s, ls);
    return p;
}

bool any_closed(const Model& m, const State& s) {
    for (std::size_t k = 0; k < m.contacts.size(); ++k) {
        if (s.modes[k] == m.contacts[k]->contact_mode()) return true;
    }
    return false;
}

// The largest penetration of any support at the state (whatever its mode) [m].
double deepest(const Model& m, const State& s) {
    double d = -std::numeric_limits<double>::infinity();
    for (const ForceElementPtr& c : m.contacts) d = std::max(d, c->contact_reading(assembler().gather(*c, s.q)).penetration);
    return d;
}

std::string text(const char* format, double a, double b = 0.0) {
    char buf[200];
    std::snprintf(buf, sizeof buf, format, a, b);
    return buf;
}

// The boundary between a (value <= 0) and b (value > 0) on the travel, to a bracket `width` of the
// travel, by the Illinois variant of regula falsi: the values here (the deepest penetration, the
// slope dV^2/dtau) are smooth in the travel, so it converges superlinearly where bisection took
// about 40 % of a pull-in run's Newton solves. A trial that fails or gives no finite value falls
// back to bisecting. Each trial starts from the state at the nearer end. Returns b's side.
// At a fold V^2 is quadratic in the travel, so a bracket of 1e-9 of the travel puts V within
// about 1e-16 of its extreme (and the travel at pull-in within 1e-9): no need to go to roundoff.
constexpr double kFoldWidth = 1e-9;

template <class Value>
State locate(const Model& m, State a, State b, bool fix_modes, int& iterations, BorderedSolver& ls, double width,
             Value value) {
    double fa = value(a), fb = value(b);
    int kept = 0;  // which end the last two trials left in place (-1 a, +1 b): Illinois halves its value
    for (int it = 0; it < 80 && std::abs(b.tau - a.tau) > width * std::abs(b.tau); ++it) {
        double t = 0.5 * (a.tau + b.tau);
        if (std::isfinite(fa) && std::isfinite(fb) && fa <= 0.0 && fb > 0.0) {
            const double secant = a.tau + (b.tau - a.tau) * (fa / (fa - fb));
            if (secant > std::min(a.tau, b.tau) && secant < std::max(a.tau, b.tau)) t = secant;
        }
        State mid = std::abs(t - a.tau) <= std::abs(t - b.tau) ? a : b;
        if (!solve_at(m, t, mid, fix_modes, iterations, ls)) {
            mid = a;
            if (!solve_at(m, 0.5 * (a.tau + b.tau), mid, fix_modes, iterations, ls)) break;
        }
        const double fm = value(mid);
        if (fm > 0.0) {
            b = mid;
            fb = fm;
            if (kept == -1) fa *= 0.5;
            kept = -1;
        } else {
            a = mid;
            fa = std::isfinite(fm) ? fm : std::numeric_limits<double>::quiet_NaN();
            if (kept == +1) fb *= 0.5;
            kept = +1;
        }
    }
    return b;
}

// The equilibrium at zero voltage, where the continuation starts.
State rest_state(const Model& m) {
    const Index n = m.K.rows();
    ForceSet at_rest = m.contacts;
    at_rest.insert(at_rest.end(), m.structural.begin(), m.structural.end());
    const StaticState rest = solve_static(m.K, at_rest, Eigen::VectorXd::Zero(n), {}, m.max_iterations);
    State s;
    s.q = rest.q;
    s.modes.assign(rest.modes.begin(), rest.modes.begin() + static_cast<std::ptrdiff_t>(m.contacts.size()));
    s.tau = m.row.dot(s.q);
    return s;
}

// Secant predictor along the branch for a step of the travel from s (previous: the point before).
State predict(const State& s, const State& previous, double step, bool has_previous) {
    State trial = s;
    if (has_previous && s.tau != previous.tau) {
        const double ratio = step / (s.tau - previous.tau);
        trial.q = s.q + ratio * (s.q - previous.q);
        trial.lambda = s.lambda + ratio * (s.lambda - previous.lambda);
    }
    return trial;
}

// The last open state and the first closed one s bracket the touch-down: where the open branch's
// deepest penetration crosses zero. Returns the largest lambda the closed branch is followed to.
double note_touchdown(const Model& m, const State& previous, const State& s, BorderedSolver& ls, PullinResult& r) {
    State a = previous, b = s;
    b.modes = a.modes;
    if (!solve_at(m, b.tau, b, true, r.newton_iterations, ls)) b = s;
    // The voltage is smooth in the travel there: a bracket at roundoff gives it at roundoff.
    const State td = locate(m, a, b, true, r.newton_iterations, ls, 4e-16, [&](const State& x) { return deepest(m, x); });
    r.touchdown = describe(m, td, ls);
    r.touchdown->contact = true;
    // Held at touch-down when the closed branch starts stable there.
    r.touchdown->stable = is_stable(m, s, ls);
    if (r.touchdown->stable) r.release_voltage = r.touchdown->voltage;
    const double ref = r.pullin ? r.pullin->voltage : r.touchdown->voltage;
    return 16.0 * ref * ref;
}

// A point s of the open branch; the first fall of lambda places the pull-in fold between the last two
// points of rising lambda and s.
void note_open_point(const Model& m, const State& previous, const State& s, BorderedSolver& ls, std::vector<State>& open,
                     PullinResult& r) {
    open.push_back(s);
    if (r.pullin || open.size() < 3 || !(s.lambda < previous.lambda)) return;
    const State& a = open[open.size() - 3];
    const State fold = locate(m, a, s, false, r.newton_iterations, ls, kFoldWidth,
                              [&](const State& x) { return -lambda_slope(m, x, ls); });
    r.pullin = describe(m, fold, ls);
    // The tangent is singular at the fold: its sign there is roundoff. The point ends the stable
    // branch and is reported as its limit, not stable.
    r.pullin->stable = false;
    open.insert(open.end() - 1, fold);
}

// Why the branch ends at s when the beam comes within 0.5 % of a bare electrode's air gap (the last
// such electrode named), or "" when it does not. A dielectric layer is a contact (DielectricContact):
// the beam lands on it and the branch goes on; a bare electrode's face is not.
std::string collapse_onto_a_pad(const Model& m, const State& s, double voltage) {
    std::string end;
    for (const PadPtr& pad : m.pads) {
        if (pad->geometry().dielectric_thickness > 0.0) continue;
        const ElectrostaticPad::Narrowest narrow = pad->narrowest(assembler().gather(*pad, s.q).q);
        if (narrow.air_gap <= 5e-3 * (pad->geometry().gap - pad->geometry().dielectric_thickness)) {
            end = "the beam collapses onto " + pad->name() +
                  text(" (it touches it at x = %.4g um, V = %.6g V on the unstable branch)", narrow.x * 1e6, voltage);
        }
    }
    return end;
}

// The frequencies at o.frequency_points voltages of the open branch; `point_done` after each.
void add_frequencies(const Model& m, const std::vector<State>& open, double top, const PullinOptions& o,
                     PullinResult& r, const std::function<void()>& point_done) {
    if (open.empty() || o.frequency_points < 2) return;
    for (int i = 0; i < o.frequency_points; ++i) {
        if (i > 0) point_done();
        const double target = top * i / (o.frequency_points - 1);
        const State* best = &open.front();
        for (const State& s : open) {
            if (std::abs(std::sqrt(std::max(s.lambda, 0.0)) - target) <
                std::abs(std::sqrt(std::max(best->lambda, 0.0)) - target)) {
                best = &s;
            }
        }
        Eigen::VectorXd force;
        SparseMatrix a;
        if (!evaluate(m, *best, force, &a)) continue;
        PullinFrequencies f;
        f.voltage = std::sqrt(std::max(best->lambda, 0.0));
        try {
            const Eigen::VectorXd omega = lowest_frequencies(a, m.M, o.frequency_count);
            for (Index k = 0; k < omega.size(); ++k) f.frequency_hz.push_back(omega[k] / (2.0 * std::numbers::pi));
        } catch (const std::runtime_error&) {
            continue;  // at the fold itself the tangent is singular: no frequencies there
        }
        if (r.frequencies.empty() || r.frequencies.back().voltage != f.voltage) r.frequencies.push_back(std::move(f));
    }
    point_done();
}

}  // namespace

PullinModel pullin_model(const Case& c) {
    if (c.electrodes.empty()) throw InputError("electrodes: the case has no [[electrodes]] (pull-in needs one)");
    if (c.beam.elements > kMaxPullinElements) {
        throw InputError("beam.elements: " + std::to_string(c.beam.elements) +
                         " elements are more than the pull-in trace takes (at most " + std::to_string(kMaxPullinElements) +
                         ", docs/electrostatics.md §4): beyond, K's roundoff moves V_PI more than the mesh does and "
                         "each Newton step costs the square of the DOFs an electrode faces; use fewer");
    }
    if (c.beam.stretching && c.beam.elements > kMaxPullinStretchingElements) {
        throw InputError("beam.elements: " + std::to_string(c.beam.elements) +
                         " elements are more than the pull-in trace takes with stretching = true (at most " +
                         std::to_string(kMaxPullinStretchingElements) +
                         ", docs/electrostatics.md §4): the stretching couples every slope, so each Newton step "
                         "solves a dense system; use fewer");
    }
    const BeamModel b = build_beam_model(c);
    Model m;
    m.K = b.K;
    m.M = b.M;
    for (const ForceElementPtr& e : b.forces) {
        if (e->is_contact()) {
            m.contacts.push_back(e);
        } else if (e->in_static_state()) {
            if (e->modes() != 1) throw std::logic_error(e->name() + ": pull-in takes only smooth elements besides contacts");
            m.structural.push_back(e);
        }
    }
    m.pads = electrode_elements(c, b.system, b.bending_position, true);
    const ElectrostaticPad& first = *m.pads.front();
    if (first.dofs().empty()) throw InputError("electrodes[0]: it faces no part of the beam that can move");
    m.row = Eigen::VectorXd::Zero(m.K.rows());
    const std::vector<double> r0 = first.mean_travel_row();
    for (std::size_t i = 0; i < r0.size(); ++i) m.row[first.dofs()[i]] += r0[i];
    m.watched = b.watched.dof;
    m.sign = first.geometry().sign;
    m.air_gap = first.geometry().gap - first.geometry().dielectric_thickness;
    m.max_iterations = c.solver.max_static_iterations;
    if (m.watched >= 0) {
        const int reduced = b.system.bending[static_cast<std::size_t>(m.watched)];
        const int global = b.system.free_dofs[static_cast<std::size_t>(reduced)];
        m.watched_x = b.system.mesh.x[static_cast<std::size_t>(global / 3)] / b.system.length;
    }
    return m;
}

PullinResult trace_pullin(const Case& c, const PullinOptions& o) { return trace_pullin(pullin_model(c), o); }

PullinResult trace_pullin(const PullinModel& m, const PullinOptions& o) {
    PullinResult r;
    r.watched_x = m.watched_x;
    BorderedSolver ls;
    State s = rest_state(m);
    std::vector<State> open;  // the open branch, for frequencies and the fold
    open.push_back(s);
    r.branch.push_back(describe(m, s, ls));

    const int budget_steps = o.steps > 0 ? o.steps : 200;
    const double full = m.air_gap / budget_steps;
    int reported = 0;  // units of the progress budget (steps, then frequency points) reported
    const auto report = [&](int units, int unused) {
        if (o.progress && units + unused > 0) o.progress(units, unused);
        reported += units + unused;
    };
    double step = full;
    State previous = s;
    const long max_points = 8L * std::max(o.steps, 1) + 200;
    double lambda_limit = std::numeric_limits<double>::infinity();
    for (long k = 0; k < max_points; ++k) {
        const double tau = s.tau + step;
        // On a dielectric the beam lands and presses into the layer: the travel may pass the air gap.
        if (tau >= m.air_gap + m.pads.front()->geometry().dielectric_thickness) {
            r.end = "the mean travel reached the air gap of electrodes[0]";
            break;
        }
        State trial = predict(s, previous, step, k > 0);
        if (!solve_at(m, tau, trial, false, r.newton_iterations, ls)) {
            step *= 0.5;
            if (step < full * 1e-9) {
                r.end = text("continuation lost at V = %.6g V (mean travel %.4g um): no equilibrium found by the smallest step",
                             std::sqrt(std::max(s.lambda, 0.0)), s.tau * 1e6);
                break;
            }
            continue;
        }
        previous = s;
        s = trial;
        step = std::min(full, 2.0 * step);

        const bool closed = any_closed(m, s);
        if (closed && !r.touchdown) lambda_limit = note_touchdown(m, previous, s, ls, r);
        if (!closed && !r.touchdown) note_open_point(m, previous, s, ls, open, r);
        if (closed && r.touchdown && !r.collapse && s.lambda < previous.lambda && any_closed(m, previous)) {
            const State fold = locate(m, previous, s, false, r.newton_iterations, ls, kFoldWidth,
                                      [&](const State& x) { return -lambda_slope(m, x, ls); });
            r.collapse = describe(m, fold, ls);
            r.collapse->stable = false;  // as at pull-in
        }
        PullinPoint p = describe(m, s, ls);
        // Release: the lowest voltage at which a closed support still holds the beam stably.
        if (p.contact && p.stable) r.release_voltage = std::min(r.release_voltage.value_or(p.voltage), p.voltage);
        r.branch.push_back(p);
        report(std::max(0, std::min(budget_steps, static_cast<int>(s.tau / full)) - reported), 0);
        r.end = collapse_onto_a_pad(m, s, p.voltage);
        if (!r.end.empty()) break;
        if (s.lambda > lambda_limit) {
            r.end = "the voltage passed 4 times the pull-in (or touch-down) voltage on the closed branch";
            break;
        }
    }
    if (r.end.empty()) r.end = "more than " + std::to_string(max_points) + " continuation points (raise --steps)";
    std::vector<State> stable_open;
    for (const State& x : open) {
        if (!r.pullin || x.tau <= r.pullin->travel) stable_open.push_back(x);
    }
    const double top = r.pullin ? r.pullin->voltage : r.touchdown ? r.touchdown->voltage : r.branch.back().voltage;
    report(0, budget_steps - reported);
    add_frequencies(m, stable_open, top, o, r, [&] { report(1, 0); });
    report(0, budget_steps + o.frequency_points - reported);
    r.lu_fallbacks = ls.fallbacks();
    return r;
}

}  // namespace vi
