#pragma once
// Why the exact event-driven solver cannot finish a run that an integrator can: the run is well posed,
// but not in the form the exact solver needs (a sum of modal exponentials per contact state, found
// events that advance time). run_simulation hands such a run to CVODE (solver.fallback).

#include <stdexcept>

namespace vi {

class ExactSolverGaveUp : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A contact state whose system matrix has (nearly) defective eigenvalues, so that no sum of modal
// exponentials represents its motion to roundoff (e.g. a mode near critical damping, shifted by the
// contacts).
class NotDiagonalisable : public ExactSolverGaveUp {
public:
    using ExactSolverGaveUp::ExactSolverGaveUp;
};

// Contact states of zero length that repeat at one instant (a damper so far above critical that the
// sign of the contact force at an opening is roundoff): time no longer advances.
class EndlessSwitching : public ExactSolverGaveUp {
public:
    using ExactSolverGaveUp::ExactSolverGaveUp;
};

// A test seam: while one lives, the exact solver gives up on every contact state with a closed
// contact as on a defective one (NotDiagonalisable, with the same message), so that the hand-over to
// CVODE is tested on any build, whatever its arithmetic decides for a state that is defective only
// to roundoff. Process-wide; one at a time.
class GiveUpOnClosedStatesForTest {
public:
    GiveUpOnClosedStatesForTest();
    ~GiveUpOnClosedStatesForTest();
    GiveUpOnClosedStatesForTest(const GiveUpOnClosedStatesForTest&) = delete;
    GiveUpOnClosedStatesForTest& operator=(const GiveUpOnClosedStatesForTest&) = delete;
    // Whether one lives (states decomposed by earlier runs are then not taken either).
    static bool active();
};

}  // namespace vi
