#pragma once
// The switch report (`vibroimpact switch-report`): a contact switch's static pull-in (V(travel),
// C-V, f-V) and its switching transient with the bounce ledger, as one page with figures
// (docs/electrostatics.md §10).

#include <string>
#include <vector>

#include "statics/pullin.hpp"
#include "impacts/simulation.hpp"
#include "io/output_files.hpp"
#include "model/case.hpp"
#include "plot/figure_gnuplot.hpp"
#include "plot/report_document.hpp"

namespace vi {

// What the page shows: the case, its pull-in trace and its transient (as `simulate` runs it).
struct SwitchStudy {
    Case c;
    PullinResult pullin;
    SimulationRun transient;
    double pullin_s = 0.0;     // wall time of the pull-in trace [s]
    double transient_s = 0.0;  // wall time of the transient [s]
};

// Runs both. Throws InputError (no electrode, no horizon) and what trace_pullin and run_simulation
// throw; StopRequested from check_run().
SwitchStudy run_switch_study(const Case& c);

// The figures: switch_pullin (V against the travel, stable and unstable), switch_cv, switch_fv and
// switch_transient (the watched point, the contact force and the voltage against time).
std::vector<FigureSpec> switch_figures(const SwitchStudy& s);

// The page: what was run, pull-in, touch-down, release, the switching transient and its bounce
// ledger (one row per contact episode), the figures, and how to rerun it.
ReportDocument switch_report(const SwitchStudy& s, const std::string& command);

// Every file: report.html, report.md, the figures (.png, .svg, .gp and their CSVs), the pull-in
// files (pullin.json, pullin_branch.csv, pullin_frequencies.csv) and the transient's (summary.json,
// history.csv, events.csv). `rendered` is in the order of `figures`.
OutputFiles switch_report_files(const SwitchStudy& s, const std::vector<FigureSpec>& figures,
                                const std::vector<RenderedFigure>& rendered, const std::string& command);

}  // namespace vi
