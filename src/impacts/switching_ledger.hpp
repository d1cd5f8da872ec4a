#pragma once
// The switching ledger of a transient under electrode voltage: closing time, bounces, time to stable
// contact, and release (or why not) after the voltage falls (docs/electrostatics.md §5).

#include <optional>
#include <string>
#include <vector>

#include "statics/contact_hold.hpp"
#include "statics/layer_hold.hpp"
#include "dynamics/transient_result.hpp"
#include "model/case.hpp"

namespace vi {

// |V| at or below this fraction of an electrode's largest |V| counts as off (the force, ~V^2, is
// then below 1e-4 of its largest value).
inline constexpr double kVoltageOffFraction = 0.01;

// When the electrodes' voltage is on: the first time any |V(t)| rises above kVoltageOffFraction of
// its largest value, and the time after which every |V(t)| stays at or below it [s]. `off` is empty
// when some voltage never falls for good (constant, step, sine, a table that ends on); both are empty
// when no electrode has a voltage.
struct VoltageWindow {
    std::optional<double> on, off;
};
VoltageWindow voltage_window(const std::vector<Electrode>& electrodes);

// One contact episode of the switching sequence (the first contact, each bounce, the stable one).
struct SwitchingContact {
    int support = 0;
    double t_on = 0.0, t_off = 0.0;  // [s] (t_off is the horizon if still closed)
    double impact_velocity = 0.0;    // contact point's velocity at onset, signed, v up [m/s]
    double peak_force = 0.0;         // [N]
    bool closed_at_end = false;
};

// Why a switch is stuck: an adhesive contact still closed at the horizon after the voltage fell and
// pulling: a support, pulled on by the beam less hard than its pull-off force, or an electrode's
// adhesive layer, which the beam peels only where it releases more strain energy than w w_e.
struct StuckBalance {
    int support = 0;               // the contact's index among the model's contacts
    std::string contact;           // "supports[i]" or "electrodes[k].dielectric"
    double restoring_force = 0.0;  // the beam's static pull off the surface (ContactHold, LayerHold) [N]
    // F_po of a support; for a layer the pull of its stuck contact lifted evenly (LayerHold) [N].
    double pull_off_force = 0.0;
    // The contact's force at the horizon, negative while it pulls [N]; a layer's, averaged over the
    // last period of mode 1 (the beam held down still vibrates).
    double contact_force = 0.0;
    std::optional<LayerHold> layer;  // a layer's peel balance
};

// The beam collapsing onto an electrode: the run ended there (ElectrostaticPad's terminal mode).
struct SwitchingCollapse {
    std::string electrode;  // "electrodes[k]"
    double time = 0.0;      // [s]
    double x = 0.0;         // where the air gap is narrowest [m]
    double voltage = 0.0;   // that electrode's V at that time [V]
    double air_gap = 0.0;   // the narrowest air gap then [m]
};

struct SwitchingLedger {
    VoltageWindow voltage;
    std::optional<double> closing_time;    // onset of the first contact episode [s]
    // Contact episodes that opened before stable contact: every separation, the chatter inside one
    // impact included (a re-closure after a flight shorter than group_gap, DESIGN.md §3).
    int bounces = 0;
    // The same bounces grouped as impacts are: those followed by a flight of at least group_gap (or by
    // no further contact); a separation after a shorter flight is chatter within one impact.
    int grouped_bounces = 0;
    double group_gap = 0.0;                // [s]: solver.group_gap, by default a quarter period of mode 1
    std::optional<double> stable_contact;  // onset of the episode that stays closed [s]
    std::vector<SwitchingContact> contacts;  // first contact up to stable contact (or all, without one)
    double peak_force = 0.0;               // largest of those [N]
    std::optional<double> release_time;    // end of the last contact, once the voltage has fallen [s]
    // never_closed, closed (still closed at the horizon), stuck (closed at the horizon after the voltage
    // fell, held by adhesion), released (opened after the voltage fell), opened_before_voltage_off,
    // bouncing (open at the horizon with the voltage still on), collapsed (the beam reached an
    // electrode, which ended the run: `collapse`; the contacts are those up to then).
    std::string state;
    std::optional<SwitchingCollapse> collapse;  // with state "collapsed"
    std::optional<StuckBalance> stuck;  // with state "stuck"
    std::string reason;  // one sentence: why that state
};

// One contact as the ledger sees it besides its episodes: its case key, and what holds it where it
// is adhesive: a support's hold (ContactHold) or a layer's peel balance (LayerHold); neither for a
// plain contact.
struct LedgerContact {
    std::string name;  // "supports[0]", "electrodes[1].dielectric"
    std::optional<ContactHold> hold;
    std::optional<LayerHold> layer;
};

// What the ledger needs besides the transient: the first circular frequency of the unsupported beam
// (a contact must last one period 2 pi / omega1 to count as stable) [rad/s]; and every contact, in
// the order of the result's contacts (ContactEpisode::support, the time history's contact columns).
SwitchingLedger switching_ledger(const TransientResult& r, const std::vector<Electrode>& electrodes, double omega1,
                                 const std::vector<LedgerContact>& contacts, double group_gap = 0.0);
// The ledger of a run read to its end as if the horizon ended it (switching_ledger without the collapse).
SwitchingLedger switching_ledger_to_end(const TransientResult& r, const std::vector<Electrode>& electrodes,
                                        double omega1, const std::vector<LedgerContact>& contacts);
// How the bounces are counted, in words, with the grouped count: for the text output and the report.
std::string bounce_text(const SwitchingLedger& l);

}  // namespace vi
