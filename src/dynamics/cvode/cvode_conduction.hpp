#pragma once
// The CVODE solver's record of when each contact with a resistance model conducts below its on
// threshold: the crossings are located on CVODE's dense output between its returns, so they do not
// depend on the history's output step. Internal to the CVODE solver (dynamics/cvode/cvode_solver.cpp).

#include <functional>
#include <vector>

#include "dynamics/cvode/cvode_system.hpp"
#include "dynamics/transient_result.hpp"

namespace vi::cvode_detail {

class ConductionRecorder {
public:
    // The state y at a time inside CVODE's last step (its interpolating polynomial).
    using DenseOutput = std::function<const double*(double)>;

    ConductionRecorder(const ModalSystem& system, TransientResult& result);
    // Some contact has a threshold to watch.
    [[nodiscard]] bool active() const { return !tracks_.empty(); }
    // The state at t = 0 in the elements' initial modes: a contact that starts closed below its
    // threshold conducts from 0.
    void start(const double* y, const std::vector<int>& modes);
    // A return of CVODE at t with state y, the modes unchanged since the previous return: a change of
    // conduction since then is located by bisection on `at`, valid from step_start to t. Between
    // returns the penetration has no interior maximum (its maxima are the contacts' watch roots, each
    // a return), so it is monotone there or falls to one minimum and rises again: the resistance
    // crosses the threshold once, or, conducting at both ends, rises above it and back around that
    // minimum, which is looked for where the penetration falls at the start and rises at the end.
    void advance(double t, const double* y, const std::vector<int>& modes, double step_start, const DenseOutput& at);
    // The elements switched mode at t (state y, the new modes): a contact that opened stops
    // conducting at t.
    void switched(double t, const double* y, const std::vector<int>& modes);
    // Stretches still on at the horizon end there; each contact's resistance at the end.
    void finish(double t_end, const double* y, const std::vector<int>& modes);

private:
    struct Track {
        int element = 0;
        std::size_t record = 0;  // index in TransientResult::conduction
        bool on = false;
        double t_last = 0.0;     // the last time it was looked at [s]
    };
    // Element e closed (in its contact mode) with a resistance below r_on at y.
    [[nodiscard]] bool conducting(const Track& k, double t, const double* y, const std::vector<int>& modes) const;
    void change(Track& k, double t, double resistance);
    // The first time in (lo, hi] at which conducting(...) == want, it being != want at lo [s].
    [[nodiscard]] double crossing(const Track& k, double lo, double hi, bool want, const std::vector<int>& modes,
                                  const DenseOutput& at) const;
    // Conducting at lo and at t: an interior minimum of the penetration where the contact stops
    // conducting is recorded as an off and an on crossing.
    void dip(Track& k, double lo, double t, const double* y, const std::vector<int>& modes, const DenseOutput& at);

    const ModalSystem& sys_;
    TransientResult& r_;
    std::vector<Track> tracks_;
};

}  // namespace vi::cvode_detail
