#pragma once
// solve_cvode: the transient solver for any force element (the nonlinear path), on SUNDIALS CVODE
// (BDF) in modal coordinates: the beam's linear part is diagonal, the elements act through the
// basis rows of their DOFs, and the Newton matrix is solved by a structured direct solver
// (dynamics/cvode/cvode_linear_solver.hpp) in O(r s^2) for r basis vectors and s element DOFs. A
// full model whose elements act on much of the beam integrates in the FE DOFs instead (O(n) a step;
// CvodeOptions::state). Switching
// elements (contacts) are handled by CVODE's root finding with a restart at every switch. Also the
// independent cross-check of the exact event-driven solver.

#include <string_view>

#include "dynamics/transient_solver.hpp"

namespace vi {

// CVODE's own settings (the common ones are TransientOptions).
struct CvodeOptions {
    double rtol = 1e-10;        // relative tolerance of every state component
    // Absolute tolerance of each component = rtol x atol_ratio x a characteristic magnitude derived
    // from the problem (cvode_system.cpp: absolute_tolerances). Most components of the modal state
    // are small (fast vectors), so the absolute tolerance is what sets the accuracy: tying it to rtol
    // makes rtol the one knob (the paper's transient: rtol 1e-8 is within 1e-7 of the exact solver,
    // 1e-10 within 5e-9; docs/model.md §13).
    double atol_ratio = 1e-4;
    // 0: every bending mode (the full FE model, an exact change of coordinates); N > 0: a
    // reduced-order model on the N lowest modes plus static corrections (solver.reduced_modes).
    int reduced_modes = 0;
    // Whether a reduced basis adds the static response to each element's load patterns (an
    // electrode's pull, a film's force over its span). A free ring-down has no prescribed load and
    // leaves them out.
    bool static_corrections = true;
    // End the run at the first contact onset (the result's t_end is then that time, the episode
    // closed_at_end): a question that the first contact answers (dynamic pull-in) needs no more.
    bool stop_at_first_contact = false;
    // Carry a flight, where every element is in a mode that exerts no force (ForceElement::free_mode:
    // open contacts and nothing else acting), in closed form: each basis vector is then a damped
    // oscillator, its switches are found by the exact solver's certified search, and CVODE steps only
    // while something acts. Off: CVODE steps through the flights too (the cross-check).
    bool free_flight = true;
    // The coordinates of a full model's state (reduced_modes = 0): `automatic` takes the FE DOFs
    // from 100 DOFs up unless a flight in closed form may come (docs/model.md §13); `modal` and
    // `nodal` force one (the cross-check of the other). A reduced model is always modal; `nodal`
    // falls back to modal where K is singular.
    enum class State { automatic, modal, nodal };
    State state = State::automatic;
};

// Integrates p from 0 to p.t_end (TransientSolver's rules; max_steps counts CVODE's internal steps,
// max_events the switches). Elements switch only at located events (their switching functions
// crossing zero upward), each followed by a restart of CVODE; an element's time stops (a load step, a
// table's corners: TimeFunction::stops) are integration stops with a restart too. The energy ledger's integrals and each contact's
// impulse are extra CVODE states. Without o.energy only the initial and final ledgers are kept, and
// each sample saves a pass over every element (6 % of the switch example's transient). Its own
// failure: std::runtime_error when CVODE fails.
TransientResult solve_cvode(const TransientProblem& p, const TransientOptions& o = {}, const CvodeOptions& c = {});

class CvodeSolver final : public TransientSolver {
public:
    explicit CvodeSolver(const CvodeOptions& c = {}) : c_(c) {}
    [[nodiscard]] std::string_view method() const override { return "cvode"; }
    [[nodiscard]] TransientResult solve(const TransientProblem& p, const TransientOptions& o) const override {
        return solve_cvode(p, o, c_);
    }

private:
    CvodeOptions c_;
};

}  // namespace vi
