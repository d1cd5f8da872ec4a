#pragma once
// The CVODE solver's record of contact episodes and extremes: episodes open and close as contact
// elements switch, peaks and extremes are updated at every return of CVODE. Internal to the CVODE
// solver (dynamics/cvode_solver.cpp).

#include <vector>

#include "dynamics/cvode/cvode_system.hpp"
#include "dynamics/transient_result.hpp"

namespace vi::cvode_detail {

class EpisodeRecorder {
public:
    EpisodeRecorder(const ModalSystem& system, TransientResult& result);
    // Element e switched from mode `from` to `to` at t (state y): an episode opens when a contact
    // enters its contact mode, and closes when it leaves it.
    void on_switch(int e, int from, int to, double t, const double* y);
    // The largest F and d of every open episode so far. An episode's peaks are at its ends, at an
    // interior maximum (located exactly by the contact's watch functions dd/dt and dF/dt) or at a stop
    // where dF/dt jumps; this runs at every return of CVODE (each step, root and stop), so all of those
    // are covered.
    void update_peaks(double t, const double* y);
    // y_max, the deepest tip deflection while a contact is closed and the first contact point's
    // maximum, after the first onset: local extrema are roots of the velocities (located by CVODE),
    // values at every return cover the ends.
    void update_extremes(double t, const double* y, const std::vector<int>& modes);
    // Episodes still open at the horizon end there.
    void close_at_end(double t_end, const double* y);

private:
    const ModalSystem& sys_;
    TransientResult& r_;
    std::vector<int> contact_of_;           // element -> contact number, -1 when not a contact
    std::vector<int> open_;                 // open episode of each contact, -1 if none
    std::vector<double> impulse_at_onset_;  // the impulse integral when it opened [N s]
};

}  // namespace vi::cvode_detail
