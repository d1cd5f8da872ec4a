#pragma once
// FreeFlight: the beam's motion in closed form while no force element acts (every element in a mode
// it declares free: ForceElement::free_mode, an open contact). In the ModalSystem's coordinates each
// basis vector is then a damped oscillator of its own, eta'' + D eta' + w^2 eta = 0, so the state at
// any time, the Rayleigh dissipation and every element's switching function are sums of exponentials
// (dynamics/signal/). Internal to the CVODE solver (dynamics/cvode/cvode_solver.cpp), which carries a
// flight this way instead of stepping through it.

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "dynamics/cvode/cvode_system.hpp"
#include "dynamics/signal/event_search.hpp"
#include "dynamics/signal/exp_signal.hpp"

namespace vi::cvode_detail {

class FreeFlight {
public:
    explicit FreeFlight(const ModalSystem& system);
    // False when some basis vector is within 1e-6 of critical damping (its two exponents merge and
    // the split into them loses digits), or on a nodal basis (no modes): the solver then steps
    // through every flight.
    [[nodiscard]] bool usable() const { return usable_; }
    // The free modes of every element in `modes`, or nullopt when one of them acts there.
    [[nodiscard]] std::optional<std::vector<FreeMode>> free_modes(const std::vector<int>& modes) const;

    // A flight from state y (ModalSystem layout) at time t0.
    void start(double t0, const double* y);
    // The state at t >= t0 into out: eta, eta' and the Rayleigh dissipation in closed form, the other
    // quadratures as at the start (no element acts).
    void state(double t, double* out) const;
    // The first time in (t0, t_end] at which element e's switching function (the smallest of its
    // free mode's parts) turns positive, or nullopt. Throws WorkLimitReached when `budget` runs out.
    [[nodiscard]] std::optional<double> first_switch(int e, const FreeMode& m, double t_end, long* budget);
    // Where a displacement row over the basis (the watched point's, a contact's) is largest over
    // [t0, t_end], if above `floor`: {value, time}; time < 0 when nothing beats floor.
    [[nodiscard]] SignalMaximum maximum(const Eigen::RowVectorXd& row, double t_end, double floor, long* budget);
    // Search evaluations so far.
    [[nodiscard]] int evaluations() const { return evaluations_; }

private:
    // The signal of wq . q + wv . v over element e's DOFs, from t0.
    [[nodiscard]] ExpSignal part_signal(int e, const LinearPart& p) const;
    [[nodiscard]] ExpSignal row_signal(const Eigen::RowVectorXd& aq, const Eigen::RowVectorXd& av) const;
    [[nodiscard]] CrossingSearch search(double t_end, long* budget) const;

    const ModalSystem& sys_;
    bool usable_ = true;
    Eigen::VectorXcd lambda_;   // exponents, one per underdamped vector, two per overdamped one [1/s]
    std::vector<int> vector_;   // the basis vector of each exponent
    Eigen::VectorXcd E_;        // eta_i(tau) = Re sum over i's exponents of E_k exp(lambda_k tau)
    Eigen::VectorXd y0_;        // the state at the start
    double t0_ = 0.0;
    double h_min_ = 0.0;        // smallest search step [s]
    int evaluations_ = 0;
};

}  // namespace vi::cvode_detail
