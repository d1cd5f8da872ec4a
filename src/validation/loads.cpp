// docs/validation.md section 9: time-dependent loads through both solvers against the closed-form
// response of a loaded mass-spring.

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "validation/loaded_oscillator.hpp"
#include "validation/report.hpp"
#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/exact/exact_solver.hpp"

namespace vi::validation_detail {

std::string section_loads(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 9. Time-dependent loads\n\n"
      << "One mass m = 1e-11 kg on a spring k = 10 N/m (omega = 1e6 rad/s), with mass-proportional "
         "damping of ratio zeta, under a point load F g(t), F = 1 uN (`validation/loaded_oscillator.hpp`). "
         "Its response is in closed form: for g = offset + sin(W t + phase) the particular solution "
         "F/m Im[e^(i (W t + phase)) / (omega^2 - W^2 + 2 i zeta omega W)] + offset F/k plus the free "
         "response that starts the motion at rest from q0 = F/(2k); for a step at t_on the step "
         "response F/k (1 - e^(-zeta omega s)(cos omega_d s + zeta omega/omega_d sin omega_d s)), "
         "s = t - t_on, added to the free motion from q0 = -0.4 F/k; for a table rising linearly "
         "from 0 to 1 over t1 = 1.3 periods and then held (undamped, from rest) "
         "F/k (t/t1 - sin(omega t)/(omega t1)), then F/k (1 - (sin omega t - sin omega (t - t1))/(omega t1)). "
         "*Response* is the largest |q - closed form| over the samples (40 a period) relative to the "
         "static deflection F/k (divided by |1 - (W/omega)^2| for the harmonic load); *ledger* the "
         "largest |E(t) + W_damper(t) - W_load(t) - E(0)| relative to the largest energy term.\n\n";
    Table t;
    t.header = {"load", "exact: response", "exact: ledger", "CVODE: response", "CVODE: ledger",
                "test asserts (exact / CVODE)"};
    auto row = [&](const std::string& name, const LoadedOscillator& lo, double periods, double scale) {
        const PiecewiseLinearProblem p = lo.problem(periods * lo.period(), lo.period() / 40.0);
        const LoadResponseError e = load_response_error(lo, solve_exact(p), scale);
        const LoadResponseError c = load_response_error(lo, solve_cvode(p), scale);
        t.add({name, err(e.response), err(e.ledger), err(c.response), err(c.ledger), "< 1e-10 / < 1e-6"});
    };
    LoadedOscillator h;
    h.g.kind = TimeFunction::Kind::harmonic;
    h.g.phase = 0.7;
    h.g.offset = 0.3;
    h.q0 = 0.5 * h.force / h.stiffness;
    for (const double ratio : {0.37, 2.3}) {
        for (const double zeta : {0.0, 0.05}) {
            h.zeta = zeta;
            h.g.frequency_hz = ratio * h.omega() / (2.0 * std::numbers::pi);
            row("harmonic, W/omega = " + fixed(ratio, 2) + ", zeta = " + fixed(zeta, 2) + ", phase 0.7, offset 0.3", h,
                6.0, h.force / h.stiffness / std::abs(1.0 - ratio * ratio));
        }
    }
    LoadedOscillator st;
    st.g.kind = TimeFunction::Kind::step;
    st.g.t_on = 0.37 * st.period();
    st.zeta = 0.05;
    st.q0 = -0.4 * st.force / st.stiffness;
    row("step at 0.37 periods, zeta = 0.05", st, 4.0, st.force / st.stiffness);
    LoadedOscillator ramp;
    ramp.g.kind = TimeFunction::Kind::table;
    ramp.g.times = {0.0, 1.3 * ramp.period()};
    ramp.g.values = {0.0, 1.0};
    row("table: ramp over 1.3 periods, then held; zeta = 0", ramp, 4.0, ramp.force / ramp.stiffness);
    s << t.str()
      << "\nThe tests (`LoadResponse.*`) run the same problems. The exact solver carries each load's "
         "time function into the closed-form particular solution of every piece (docs/model.md "
         "section 12), so its error is roundoff; CVODE integrates it.\n\n";
    report_progress(o, "section 9: time-dependent loads");
    return s.str();
}

}  // namespace vi::validation_detail
