// Section 11 of docs/validation.md: the example switch stepped past its dynamic collapse, the FE
// model's answer (closed on its stop, or collapsed onto its electrode, and when) against an
// independent reduced-order model, and the threshold voltage between the two by both.

#include <cmath>
#include <sstream>
#include <string>

#include "impacts/simulation.hpp"
#include "validation/report.hpp"
#include "validation/switch_collapse_reference.hpp"

namespace vi::validation_detail {
namespace {

// The FE model's answer at a step of `voltage`.
struct FeAnswer {
    bool collapsed = false;
    double closing_time = 0.0, collapse_time = 0.0, collapse_x = 0.0;  // [s], [s], [x/l]
};

FeAnswer fe_answer(Case c, double voltage) {
    c.electrodes.at(0).voltage = voltage;
    SimulationOptions so;
    so.energy = false;
    const SimulationRun r = run_simulation(c, so);
    FeAnswer a;
    if (!r.result.episodes.empty()) a.closing_time = r.result.episodes.front().t_on;
    if (r.result.ended_by) {
        a.collapsed = true;
        a.collapse_time = r.result.ended_by->t;
        a.collapse_x = r.result.ended_by->reading.x / c.beam.length;
    }
    return a;
}

// The lowest collapsing step voltage by bisection of the FE model in [lo, hi], to `width`.
VoltageBracket fe_threshold(const Case& c, double lo, double hi, double width) {
    while (hi - lo > width) {
        const double mid = 0.5 * (lo + hi);
        (fe_answer(c, mid).collapsed ? hi : lo) = mid;
    }
    return {lo, hi};
}

std::string outcome(bool collapsed, double closing, double collapse, double x) {
    std::string s = "closes at " + us(closing, 4) + " us";
    if (collapsed) s += ", collapses at " + us(collapse, 4) + " us, x/l " + fixed(x, 3);
    return s;
}

}  // namespace

CantileverSwitchSpec switch_spec(const Case& c) {
    CantileverSwitchSpec s;
    const Beam& b = c.beam;
    s.length = b.length;
    s.width = b.width;
    s.thickness = b.thickness;
    s.youngs_modulus = c.material.effective_modulus();
    s.density = c.material.density;
    const Electrode& e = c.electrodes.at(0);
    s.electrode_from = e.from;
    s.electrode_to = e.to;
    s.electrode_gap = e.gap;
    s.electrode_width = e.width > 0.0 ? e.width : b.width;
    const Support& st = c.supports.at(0);
    s.stop_gap = -st.surface;
    s.stop_stiffness = st.stiffness;
    s.stop_damping_ratio = st.damping_ratio.value_or(0.0);
    s.damping_ratio_1 = c.damping.ratio1;  // modes 1 and 2 in the example
    s.damping_ratio_2 = c.damping.ratio2;
    s.horizon = c.solver.horizon;
    return s;
}

std::string section_switch_collapse(const ValidationOptions& o) {
    std::ostringstream s;
    const Case& c = o.switch_example;
    s << "## 11. A closed switch collapsing onto its electrode\n\n"
      << "The example switch (`" << o.switch_example_path
      << "`: the paper's nickel cantilever, an electrode under x/l 0.1 .. 0.9 across 2 um, a stop 1.5 um under "
         "the free end, Kc = 1000 N/m, zeta_c = 0.2, Rayleigh damping 0.005 in modes 1 and 2) stepped from rest to "
         "a voltage V at t = 0 and held for its 50 us. Above a threshold the closed beam does not settle on its "
         "stop: it snaps through onto the electrode, and the run ends there with that answer (the narrowest air "
         "gap at 1 % of the gap: docs/electrostatics.md §2). The FE model (m = 50, CVODE on the full model, rtol "
         "1e-8 as in the example) against an independent reduced-order model (`validation/"
         "switch_collapse_reference.hpp`; no code shared with the FE model): Galerkin on the analytic "
         "clamped-free Euler-Bernoulli modes (16 unless said), the parallel-plate force integrated over the "
         "electrode by Gauss-Legendre (60 x 3 points), the stop's Kelvin-Voigt force at the free end, classical "
         "RK4 at 1 ns (shortened as the gap closes) with each contact switch located by bisection of the step.\n\n";
    Table t;
    t.header = {"V [V]", "FE model", "reduced-order model", "closing time rel. diff."};
    const CantileverSwitchSpec spec = switch_spec(c);
    for (const double v : {80.0, 85.0, 90.0, 95.0, 100.0, 120.0}) {
        report_progress(o, "switch collapse: " + num(v, 3) + " V");
        const FeAnswer fe = fe_answer(c, v);
        const SwitchRomRun rom = cantilever_switch_rom(spec, v);
        t.add({num(v, 3), outcome(fe.collapsed, fe.closing_time, fe.collapse_time, fe.collapse_x),
               outcome(rom.collapsed, rom.closing_time, rom.collapse_time, rom.collapse_x),
               err(rel(fe.closing_time, rom.closing_time))});
    }
    s << t.str() << "\n";
    if (o.quick) return s.str();

    report_progress(o, "switch collapse: thresholds");
    Table th;
    th.header = {"model", "stays closed at [V]", "collapses at [V]"};
    const auto add = [&](const std::string& name, const VoltageBracket& b) {
        th.add({name, fixed(b.stays, 3), fixed(b.collapses, 3)});
    };
    add("FE, m = 50, rtol 1e-8 (the example)", fe_threshold(c, 85.0, 90.0, 0.01));
    Case fine = c;
    fine.solver.rtol = 1e-10;
    fine.beam.elements = 100;
    add("FE, m = 100, rtol 1e-10", fe_threshold(fine, 85.0, 90.0, 0.01));
    for (const int modes : {12, 16, 20}) {
        CantileverSwitchSpec r = spec;
        r.modes = modes;
        add("reduced-order, " + std::to_string(modes) + " modes, RK4 at 1 ns", cantilever_switch_rom_threshold(r, 85.0, 90.0, 0.01));
    }
    CantileverSwitchSpec half = spec;
    half.step = 0.5e-9;
    add("reduced-order, 16 modes, RK4 at 0.5 ns", cantilever_switch_rom_threshold(half, 85.0, 90.0, 0.01));
    s << "The threshold, bisected to 0.01 V by each model (`CollapseCases.ExampleSwitchCollapseThresholdAgreesWithAn"
         "IndependentModel` asserts that the FE model stays closed 0.05 V below the reduced-order model's bracket "
         "and collapses 0.05 V above it). The same by hand: `vibroimpact sweep "
      << o.switch_example_path << " --set 'electrodes[0].voltage=86:86.6:7'` (the sweep's `switching_state` column).\n\n"
      << th.str() << "\n";
    return s.str();
}

}  // namespace vi::validation_detail
