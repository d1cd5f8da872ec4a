#pragma once
// TransientResult: sampled time history, contact episodes and energy ledger of one transient.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "forces/force_element.hpp"

namespace vi {

// One stretch of contact of one contact element (docs/model.md §14).
struct ContactEpisode {
    int support = 0;              // index of the contact element
    double t_on = 0.0;            // onset [s]
    double t_off = 0.0;           // end [s] (the horizon if still closed; see `closed_at_end`)
    double v_in = 0.0;            // velocity of the contact point at onset [m/s] (dv/dt, signed)
    double v_out = 0.0;           // velocity of the contact point at separation [m/s]
    double peak_force = 0.0;      // largest F during the episode [N]
    double peak_penetration = 0.0;  // largest d during the episode [m]
    double impulse = 0.0;         // integral of F over the episode [N s]
    bool closed_at_end = false;   // still in contact when the horizon ended
    // Energy dissipated in the contact over the episode [J] (its damper, and the stored energy it
    // drops on opening with d > 0); NaN where the solver does not record it (the exact solver).
    double contact_energy = std::numeric_limits<double>::quiet_NaN();
    // The contact's peak surface pressure at peak_penetration [Pa] (ForceElement::contact_pressure);
    // NaN for a law without a contact area.
    double peak_pressure = std::numeric_limits<double>::quiet_NaN();
    // Whether peak_pressure passed the contact's yield onset; empty without a yield strength.
    std::optional<bool> yielded;
};

// Energy terms [J], each named by the kind of element it comes from; with no damping, kinetic + strain
// + contact_spring + electrical - external_work is conserved (external_work includes the electrodes'
// source work, docs/electrostatics.md §2), and with damping the three dissipated terms make up the
// difference.
struct EnergyLedger {
    double kinetic = 0.0;             // 1/2 v^T M v
    double strain = 0.0;              // 1/2 q^T K q
    double contact_spring = 0.0;      // sum of 1/2 Kc d^2 over closed contacts
    double electrical = 0.0;          // the electrodes' stored energy, -C V^2 / 2 (co-energy's negative)
    double rayleigh_dissipated = 0.0; // integral of v^T C v dt
    double contact_dissipated = 0.0;  // integral of Cc (dd/dt)^2 dt over closed contacts
    double film_dissipated = 0.0;     // integral of the squeeze films' dissipated power dt
    double external_work = 0.0;       // integral of Q(t)^T v dt, contact surfaces' static part excluded
};

// Samples at the output step: the time history the CSV holds.
struct TimeHistory {
    std::vector<double> t;                          // [s]
    std::vector<double> watched_v, watched_velocity;  // the watched point's v [m] and dv/dt [m/s]
    std::vector<std::vector<double>> contact_v;     // per contact: v at the contact point [m]
    std::vector<std::vector<double>> contact_velocity;  // [m/s]
    std::vector<std::vector<double>> contact_force; // F (0 when open) [N]
    std::vector<EnergyLedger> energy;
    // The whole beam at every TransientOptions::field_every-th sample and the last (empty without):
    // the index of the sample in t, and the displacement of every bending DOF there [m, rad].
    std::vector<std::size_t> field_sample;
    std::vector<std::vector<double>> field_q;
};

// Whether the sample with this index is a frame of the field: every `every`-th and the last of `count`.
inline bool is_field_sample(long index, long every, long count) {
    return every > 0 && (index % every == 0 || index == count - 1);
}

// Where the solver's time went, for benchmarks [s of wall time] and counts.
struct SolverStats {
    double decomposition_s = 0.0;
    double propagation_s = 0.0;
    double event_location_s = 0.0;
    int decompositions = 0;
    int events = 0;
    int steps = 0;                 // CVODE internal steps, or exact-solver evaluations
    // Exact solver: event-search steps of the smallest length that no bound proved free of a
    // crossing, and the largest upper bound of the watched function over one of them, relative to
    // that function's size [-] (event_search.hpp: how deep a contact missed there could have gone).
    int unproven_steps = 0;
    double unproven_excess = 0.0;
    // Exact solver: contacts found on a tangency (F at roundoff, switching back at once) whose state
    // was decided by the sign of F just ahead (docs/model.md §12); each also counts as unproven.
    int tangencies = 0;
    // Exact solver: when the motion fell below roundoff of its largest energy with nothing left to
    // change the forcing, so that the rest of the horizon was one piece at rest [s]; -1 if never.
    double at_rest_from = -1.0;
    // CVODE: the basis it integrated in (every bending mode, or a reduced-order model's modes plus
    // static corrections), and how far that basis is from the initial displacement (0 when full).
    int basis_vectors = 0;
    int basis_modes = 0;
    double initial_projection_error = 0.0;
    // CVODE: the full model's state was in the FE DOFs, not modal coordinates (docs/model.md §13).
    bool nodal_state = false;
    // CVODE: flights carried in closed form (CvodeOptions::free_flight) instead of stepped.
    int free_flights = 0;
    std::string method;            // "exact" or "cvode"
    // Why the exact solver handed the run to CVODE (a contact state it could not decompose), or
    // empty when the method that ran is the one chosen.
    std::string fallback_reason;
};

// Exact extremes of the watched point and of the first contact's point after the first contact
// begins (docs/model.md §14: y_max and the deepest deflection), located by root finding.
struct Extremes {
    bool valid = false;           // false when no contact ever began
    double watched_max = 0.0;     // largest v of the watched point [m]
    double watched_max_t = 0.0;   // when [s]
    double watched_min = 0.0;     // smallest v of the watched point [m]
    double watched_min_t = 0.0;
    double contact_max = 0.0;     // largest v at contact 0 [m]
};

// A force element that ended the run before the horizon by entering a terminal mode
// (ForceElement::ends_run): which one, when, and its reading there.
struct RunEndEvent {
    int element = -1;      // index among the problem's force elements
    std::string name;      // its case key, e.g. "electrodes[0]"
    double t = 0.0;        // [s], the run's t_end
    RunEnd reading;
};

// One stretch during which a contact conducts as a threshold detector sees it: closed with its
// resistance below the contact's on threshold r_on (docs/hertz-contact.md §7).
struct ConductionStretch {
    double t_on = 0.0;             // the resistance falls below r_on [s]
    double t_off = 0.0;            // it rises to r_on or the contact opens [s] (the horizon if still on)
    double min_resistance = 0.0;   // smallest resistance in the stretch [ohm]
    bool on_at_end = false;        // still below r_on when the horizon ended
};

// A contact with a resistance model (ForceElement::contact_resistance) over the run, recorded at the
// solver's own steps and events, not at the history's samples.
struct ContactConduction {
    int contact = 0;  // index among the contacts (ContactEpisode::support)
    // Its on threshold [ohm]; NaN when none is set, and then no stretches are recorded.
    double r_on = std::numeric_limits<double>::quiet_NaN();
    std::vector<ConductionStretch> stretches;  // in time order
    double end_resistance = std::numeric_limits<double>::infinity();  // at t_end; +inf when open [ohm]
};

struct TransientResult {
    TimeHistory history;
    std::vector<ContactEpisode> episodes;  // in onset order
    EnergyLedger initial_energy;           // at t = 0
    EnergyLedger final_energy;             // at t_end
    Extremes extremes;
    double t_end = 0.0;
    std::optional<RunEndEvent> ended_by;   // set when an element's terminal mode ended the run
    std::vector<ContactConduction> conduction;  // per contact with a resistance model (CVODE only)
    SolverStats stats;
};

}  // namespace vi
