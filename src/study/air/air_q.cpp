#include "study/air/air_q.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dynamics/cvode/cvode_solver.hpp"
#include "dynamics/transient_start.hpp"
#include "forces/force_assembly.hpp"
#include "modal/eigen_solver.hpp"
#include "io/csv_writer.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

// Tip maxima of a sampled history, each refined by the parabola through it and its neighbours.
struct Maximum {
    double t = 0.0, v = 0.0;
};

// The maxima of the watched displacement above `floor` x its largest excursion.
std::vector<Maximum> watched_maxima(const TimeHistory& h, double floor) {
    std::vector<Maximum> out;
    double largest = 0.0;
    for (double v : h.watched_v) largest = std::max(largest, std::abs(v));
    for (std::size_t i = 1; i + 1 < h.t.size(); ++i) {
        const double a = h.watched_v[i - 1], b = h.watched_v[i], c = h.watched_v[i + 1];
        if (!(b > a && b >= c && b > floor * largest)) continue;
        const double curvature = a - 2.0 * b + c;
        const double shift = curvature < 0.0 ? 0.5 * (a - c) / curvature : 0.0;  // in samples, |shift| <= 1/2
        const double dt = h.t[i + 1] - h.t[i];
        out.push_back({h.t[i] + shift * dt, b - 0.25 * (a - c) * shift});
    }
    return out;
}

// Modes the ring-down keeps.
constexpr int kAirQModes = 4;

}  // namespace

Case air_q_case(const Case& base, double gap) {
    if (base.beam.elements > kMaxAirQElements) {
        throw InputError("beam.elements: " + std::to_string(base.beam.elements) + " elements are more than air-q takes (at most " +
                         std::to_string(kMaxAirQElements) + ", docs/squeeze-film.md §5): its ring-downs evaluate the film at "
                         "every quadrature point, and Q of mode 1 is mesh-converged to 5e-8 at 20 elements; use fewer");
    }
    Case c = base;
    if (!c.air) c.air = Air{};
    c.air->film = true;
    for (Electrode& e : c.electrodes) {
        e.voltage = 0.0;
        e.waveform = Waveform{};
        e.time = TimeFunction{};
    }
    if (c.electrodes.empty() && c.films.empty()) c.films.push_back(Film{0.0, 1.0, Side::below, gap, {}});
    c.supports.clear();
    c.loads.clear();
    c.damping = RayleighDamping{};
    c.initial = InitialState{};
    c.initial.kind = InitialState::Kind::rest;
    c.solver.method = SolverSettings::Method::cvode;
    c.solver.reduced_modes = 0;
    return c;
}

AirQPoint air_q_point(const Case& base, double pressure, const AirQOptions& o) {
    Case c = base;
    // A mean free path the case states holds at its own pressure; kinetic theory scales it as 1/p.
    if (c.air->mean_free_path) c.air->mean_free_path = *c.air->mean_free_path * c.air->pressure / pressure;
    c.air->pressure = pressure;
    const BeamModel model = build_beam_model(c);
    TransientProblem p = transient_problem(model, transient_start(c, model));
    const double w1 = model.omega1;
    // The model's first mode: lowest_modes of the same matrices, as the model computed it.
    Eigen::VectorXd phi = model.modes.shapes.col(0);
    const double m1 = phi.dot(p.M * phi);
    // c1 = -phi^T (df/dv at rest) phi: the films' modal damping [kg/s].
    double c1 = 0.0;
    ElementAssembler a;
    for (const ForceElementPtr& e : p.forces) {
        a.gather_rest(*e);
        a.tangent(0);
        const std::size_t n = e->dofs().size();
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; j < n; ++j) c1 -= phi[e->dofs()[i]] * a.dfdv()[i * n + j] * phi[e->dofs()[j]];
        }
    }
    AirQPoint out;
    out.pressure = pressure;
    if (!model.films.empty()) {
        out.knudsen = model.films.front().knudsen;
        out.viscosity_ratio = model.films.front().viscosity_ratio;
        out.squeeze_number = model.films.front().squeeze_number;
    }
    out.q_modal = w1 * m1 / c1;

    // Ring-down: the first mode alone, its tip moving at amplitude x gap x omega1.
    const double gap = model.films.empty() ? 1e-6 : model.films.front().gap;
    phi *= o.amplitude * gap * w1 / std::abs(phi[p.watched_dof]);
    p.v0 = phi;
    const double period = 2.0 * std::numbers::pi / w1;
    p.t_end = o.periods * period;
    p.output_step = period / o.samples;
    CvodeOptions co;
    // The ring-down measures Q from the decay of its maxima, a fraction pi periods / Q of the
    // amplitude; errors of rtol in the amplitude then give rtol Q / (pi periods) in Q: 1e-4 of Q is
    // kept by an rtol of 1e-4 of that decay (at most 1e-8; 1e-10 throughout took 2.5 times the steps).
    const double decay = std::numbers::pi * o.periods / std::max(out.q_modal, 1.0);
    co.rtol = std::clamp(1e-5 * decay, 1e-12, 1e-8);
    // The ring-down starts at a known amplitude, the scale its tolerances need: the transients' rule
    // of 1e-4 rtol times a characteristic magnitude (cvode_solver.hpp) serves contacts, whose fast
    // vectors are small, and here held the steps to 1e-14 of the motion (285 000 steps for 10
    // periods of the switch example at m = 20, 10 s for the 17 pressures; 69 000 and 2.4 s with this).
    co.atol_ratio = 1.0;
    // The first modes and the film's static corrections: without structural damping the full model's
    // undamped high modes hold CVODE's BDF steps to their period (4 million steps for 20 us of the
    // base case, measured), a stability limit, not accuracy. The uniform film's damping matrix is
    // (c / rho A) M, so the modes do not couple except through the film's nonlinearity.
    co.reduced_modes = kAirQModes;
    // Without the films' static corrections: a ring-down has no prescribed load, and a film over a
    // short span by the clamp corrects with a stiff, undamped vector whose period held CVODE's steps
    // (the switch example with a second electrode from x/l = 0 to 0.1: 27 s of CPU for the 17
    // pressures, 0.7 s without, Q of the ring-down within 1e-5 of it at 1 atm, 1.5e-3 at 1 Pa; a
    // film over the whole beam gives the same Q to every digit printed either way).
    co.static_corrections = false;
    const TransientResult r = solve_cvode(p, {}, co);
    // Maxima within 1e5 absolute tolerances of zero carry the solver's error, not the film's decay,
    // above 1e-5 of themselves (a ring-down at Q = 1 falls 20 times a period, to 1e-7 in 6).
    const std::vector<Maximum> m = watched_maxima(r.history, std::max(1e-6, 1e5 * co.rtol * co.atol_ratio));
    out.maxima = static_cast<int>(m.size());
    if (m.size() >= 3) {
        const double span = m.back().t - m.front().t;
        const double decay = std::log(m.front().v / m.back().v) / span;
        const double wd = 2.0 * std::numbers::pi * static_cast<double>(m.size() - 1) / span;
        out.q_ringdown = std::sqrt(wd * wd + decay * decay) / (2.0 * decay);
    }
    return out;
}

std::vector<double> air_q_pressures() {
    std::vector<double> p{101325.0};
    for (int k = 15; k >= 0; --k) p.push_back(std::pow(10.0, k / 3.0));  // 1e5 .. 1 Pa
    return p;
}

std::string air_q_csv(const std::vector<AirQPoint>& points) {
    CsvTable t;
    t.header = {"pressure_pa", "knudsen", "viscosity_ratio", "squeeze_number", "q_modal", "q_ringdown", "maxima"};
    for (const AirQPoint& x : points) {
        t.add_row({csv_number(x.pressure), csv_number(x.knudsen), csv_number(x.viscosity_ratio), csv_number(x.squeeze_number),
                   csv_number(x.q_modal), csv_number(x.q_ringdown), csv_count(x.maxima)});
    }
    return t.str();
}

FigureSpec air_q_figure(const std::vector<AirQPoint>& points, const std::string& case_name) {
    FigureSpec f;
    f.name = "air_q";
    f.title = "Quality factor of mode 1 against air pressure";
    f.caption = "Case ";
    f.caption.append(case_name).append(
                ": Q of the first bending mode with the squeeze film alone (no structural damping), from the film's "
                "modal damping at rest (line) and from ring-down transients (points; none where the beam is "
                "overdamped). docs/squeeze-film.md");
    f.data = {{"air_q.csv", air_q_csv(points)}};
    f.plot = "set grid\nset logscale xy\nset format x '10^{%T}'\nset xlabel 'pressure  [Pa]'\n"
             "set ylabel 'Q of mode 1'\nset key top right\n"
             "plot 'air_q.csv' using 1:5 with lines lw 2 lc rgb '#1f77b4' title 'modal: {/Symbol w}_1 m_1 / c_1', "
             "'' using 1:6 with points pt 7 ps 1.2 lc rgb '#d62728' title 'ring-down transient'\n";
    return f;
}

}  // namespace vi
