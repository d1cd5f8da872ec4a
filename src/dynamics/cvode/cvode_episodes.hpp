#pragma once
// The CVODE solver's record of contact episodes and extremes: episodes open and close as contact
// elements switch, peaks and extremes are updated at every return of CVODE. Internal to the CVODE
// solver (dynamics/cvode/cvode_solver.cpp).

#include <functional>
#include <vector>

#include "dynamics/cvode/cvode_system.hpp"
#include "dynamics/transient_result.hpp"

namespace vi::cvode_detail {

class EpisodeRecorder {
public:
    // The state y at a time inside CVODE's last step (its interpolating polynomial).
    using DenseOutput = std::function<const double*(double)>;

    EpisodeRecorder(const ModalSystem& system, TransientResult& result);
    // Whether some episode is open (a contact is closed).
    [[nodiscard]] bool any_open() const;
    // Adds each closed contact's dissipated power integrated over [lo, hi] (modes unchanged there,
    // inside CVODE's last step) to its open episode: 2-point Gauss-Legendre on the dense output, so
    // the energy is read off the solution without a quadrature in CVODE's state (which would change
    // its error norm and so its steps).
    void add_dissipation(double lo, double hi, const std::vector<int>& modes, const DenseOutput& at);
    // Element e switched from mode `from` to `to` at t (state y): an episode opens when a contact
    // enters its contact mode, and closes when it leaves it; the stored energy the contact drops (or
    // takes) at the switch is booked in its episode as dissipated (as the run's ledger books it).
    void on_switch(int e, int from, int to, double t, const double* y);
    // The largest F and d of every open episode so far. An episode's peaks are at its ends, at an
    // interior maximum (located exactly by the contact's watch functions dd/dt and dF/dt) or at a stop
    // where dF/dt jumps; this runs at every return of CVODE (each step, root and stop), so all of those
    // are covered.
    void update_peaks(double t, const double* y);
    // y_max, the watched point's deepest deflection while a contact is closed and the first contact
    // point's maximum, after the first onset: local extrema are roots of the velocities (located by CVODE),
    // values at every return cover the ends.
    void update_extremes(double t, const double* y, const std::vector<int>& modes);
    // Episodes still open at the horizon end there.
    void close_at_end(double t_end, const double* y);

private:
    // An episode of element e ends: its peak pressure and whether it passed the yield onset.
    void close(int e, ContactEpisode& ep) const;

    const ModalSystem& sys_;
    TransientResult& r_;
    std::vector<int> contact_of_;           // element -> contact number, -1 when not a contact
    std::vector<int> open_;                 // open episode of each contact, -1 if none
    std::vector<double> impulse_at_onset_;  // the impulse integral when it opened [N s]
};

}  // namespace vi::cvode_detail
