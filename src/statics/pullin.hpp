#pragma once
// Static pull-in of a beam under its electrodes: the equilibrium branch traced against the mean
// travel over the first electrode (displacement control, so the unstable branch is followed, not
// jumped), with pull-in, touch-down on a support, release and the frequencies under bias
// (docs/electrostatics.md §4).

#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fem/system.hpp"
#include "forces/electrostatic_pad.hpp"
#include "forces/force_set.hpp"
#include "model/case.hpp"

namespace vi {

// Most elements of a pull-in trace: the example switch's V_PI is 58.415739 V at m = 200, 58.415745 at
// 400, then moves with K's roundoff (5 m^4 eps: 58.415728 at 600, 58.415672 at 800), while the work
// of each Newton step grows with the square of the DOFs an electrode faces (its dense tangent
// block) and Newton's steps with the roundoff (317 at m = 200, 952 at 400, 2517 at 800: 0.09, 0.55,
// 5 s; m = 1000 gave no answer in 120 s).
inline constexpr int kMaxPullinElements = 400;
// With mid-plane stretching the tangent is dense (the axial force couples every slope): a bridge's
// trace took 3.9 s at 200 elements and 26 s at 400.
inline constexpr int kMaxPullinStretchingElements = 200;

struct PullinOptions {
    int steps = 200;          // continuation steps over the electrode's air gap
    int frequency_points = 16; // voltages (0 .. V_PI) at which the lowest modes are computed
    int frequency_count = 3;   // modes per voltage
    // Sees the work as it goes, in units of the budget steps + frequency_points: (n, 0) as the mean
    // travel passes n more step lengths (air gap / steps) and after each frequency point, and
    // (0, the rest) when the branch ends before the gap.
    std::function<void(int units, int unused)> progress;
};

// One equilibrium: all electrodes at `voltage`.
struct PullinPoint {
    double travel = 0.0;         // mean travel toward electrodes[0] over its span [m]
    double voltage = 0.0;        // [V]
    double capacitance = 0.0;    // sum over the electrodes [F]
    double watched_travel = 0.0; // travel toward electrodes[0] of the watched point (free end or mid-span) [m]
    double contact_force = 0.0;  // sum of the closed supports' forces [N]
    bool contact = false;        // some support closed
    bool stable = false;         // the tangent stiffness is positive definite
};

struct PullinFrequencies {
    double voltage = 0.0;             // [V]
    std::vector<double> frequency_hz; // lowest bending modes about that equilibrium (supports closed as springs)
};

struct PullinResult {
    std::vector<PullinPoint> branch;            // in order of travel
    std::optional<PullinPoint> pullin;          // the fold of the open branch, if one comes before contact
    std::optional<PullinPoint> touchdown;       // where a support first closes
    std::optional<double> release_voltage;      // lowest voltage holding a closed support [V]
    std::optional<PullinPoint> collapse;        // the fold of the closed branch (onto the electrode)
    std::vector<PullinFrequencies> frequencies; // along the open branch, 0 .. its largest stable voltage
    std::string end;                            // why the branch ends
    double watched_x = 0.0;                     // x/l of the watched point
    int newton_iterations = 0;
    int lu_fallbacks = 0;  // Newton steps that needed the sparse LU of the bordered matrix (bordered_solver.hpp)
};

// What the continuation works on: the beam's stiffness and mass over its bending DOFs, the contact
// elements, the smooth structural elements (their force and tangent join K q and K), the electrodes
// at 1 V, and r with r . q the mean travel toward electrodes[0] [m].
struct PullinModel {
    SparseMatrix K, M;                                       // [N/m], [kg]
    std::vector<ForceElementPtr> contacts;                   // contact elements (their static modes)
    std::vector<ForceElementPtr> structural;                 // smooth elements acting at rest (mid-plane stretching)
    std::vector<std::shared_ptr<const ElectrostaticPad>> pads;  // every electrode at 1 V
    Eigen::VectorXd row;                                     // r [-]
    int watched = -1;                                        // DOF of the watched point's v, or -1
    double watched_x = 0.0;                                  // its x/l
    double sign = -1.0;                                      // electrodes[0]'s pull direction in v
    double air_gap = 0.0;                                    // electrodes[0]'s air gap [m]
    int max_iterations = 200;                                // Newton iterations per point
};

// The model of a case: InputError when it has no electrode, more than kMaxPullinElements elements,
// or its first electrode faces nothing that moves.
PullinModel pullin_model(const Case& c);

// Traces m's equilibria from its rest state (the supports' static state at 0 V).
PullinResult trace_pullin(const PullinModel& m, const PullinOptions& o = {});

// Traces c's equilibria. Throws InputError when c has no electrode or more than kMaxPullinElements
// elements, WorkLimitReached when a
// step takes more than solver.max_static_iterations Newton iterations even at the smallest
// step, std::runtime_error when the tangent is singular, StopRequested from check_run().
PullinResult trace_pullin(const Case& c, const PullinOptions& o = {});

}  // namespace vi
