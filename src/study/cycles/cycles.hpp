#pragma once
// The `cycles` study: a switch driven through N actuation cycles by its electrodes' voltage
// waveform repeated with a period P, computed as one transient of N P; per cycle the switching
// ledger's bounces, the contact energy, the peak force and Hertz pressure, the impacts past yield
// onset and an energy wear estimate, and the trend over the cycles (docs/cycles.md).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "impacts/electrical_ledger.hpp"
#include "impacts/impact_summary.hpp"
#include "impacts/switching_ledger.hpp"
#include "model/case.hpp"

namespace vi {

// The most cycles one study runs (`--cycles`): each is a transient of its own length, and the
// results of all are held in memory.
inline constexpr int kMaxCycles = 100000;

struct CycleSettings {
    int cycles = 0;         // N, 1..kMaxCycles
    double period = 0.0;    // P [s]; 0: the case's solver.horizon
};

// One actuation cycle, [t_start, t_start + P), its times from t_start.
struct CycleRecord {
    int index = 0;                  // 0-based
    double t_start = 0.0;           // [s]
    SwitchingLedger switching;      // of the contact episodes that begin in the cycle
    std::vector<Impact> impacts;    // impacts that begin in the cycle (times from t_start)
    ContactDamage damage;           // their sums
    int electrical_bounces = -1;    // of the first contact with r_on; -1 without one
    double wear_volume = 0.0;       // sum over supports of K E / H [m^3]; NaN without wear keys
};

// A least-squares line through the cycles' values: value ~ first + slope (cycle index).
struct CycleTrend {
    double slope = 0.0;      // per cycle
    double intercept = 0.0;  // at cycle 0
    double first = 0.0, last = 0.0;  // the first and last cycle's values
};

struct CyclesResult {
    CycleSettings settings;           // period resolved
    std::vector<CycleRecord> cycles;
    CycleTrend energy_trend;          // contact energy [J]
    CycleTrend bounce_trend;          // switching bounces [-]
    CycleTrend peak_force_trend;      // [N]
    double total_contact_energy = 0.0;  // [J]
    double total_wear_volume = 0.0;     // [m^3]; NaN without wear keys
    bool wear = false;                  // some support has wear_coefficient and hardness
    int yield_impacts = 0;
    bool yield_known = false;
    int steps = 0;                      // CVODE's steps over the whole run
    std::string method;                 // the solver that ran
};

// The electrodes of c with their waveform g(t) on [0, P) repeated N times (a pulse, ramp, two-step or
// table drive as a table of N copies of its knots; a sine as it is, being periodic). Throws
// InputError "electrodes[k].waveform: ..." for a drive that does not repeat within P (a constant,
// a step, a table reaching past P) and "--cycles"/"--period" for values out of range.
Case cycled_case(const Case& c, const CycleSettings& s);

// Runs the study; `progress` (if given) is called with the cycles completed so far as the run goes.
// Throws what run_simulation throws.
CyclesResult run_cycles(const Case& c, CycleSettings s, const std::function<void(int)>& progress = {});

// The least-squares line through ys (index 0, 1, ...); all zero for no value.
CycleTrend cycle_trend(const std::vector<double>& ys);

}  // namespace vi
