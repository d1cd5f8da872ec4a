#include "study/paper/report.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "plot/beam_animation.hpp"
#include "plot/chart_json.hpp"
#include "study/paper/study.hpp"
#include "study/paper/figures.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {


std::string seconds(double s) { return decimals(s, 2) + " s"; }

void summary(ReportDocument& d, const std::vector<Claim>& claims) {
    int counts[4] = {0, 0, 0, 0};
    for (const Claim& c : claims) ++counts[static_cast<int>(c.verdict)];
    d.heading(2, "Summary", "summary");
    d.paragraph(std::to_string(claims.size()) + " claims of the paper checked: " + std::to_string(counts[0]) + " agree, " +
                std::to_string(counts[1]) + " agree in part, " + std::to_string(counts[2]) + " disagree" +
                (counts[3] ? ", " + std::to_string(counts[3]) + " could not be computed" : std::string()) +
                ". Where the model disagrees, it says so below with both numbers; no parameter was tuned to make a claim agree "
                "(every parameter the paper does not give is listed with its value and the reason for it).");
    std::vector<std::string> items;
    for (const Claim& c : claims) {
        if (c.verdict == Verdict::agrees) continue;
        items.push_back(std::string(verdict_name(c.verdict)) + " (" + c.where + "): the paper: " + c.paper + ". Ours: " + c.ours + ".");
    }
    if (!items.empty()) {
        d.paragraph("Where we do not simply agree:");
        d.list(items);
    }
}

void claims_table(ReportDocument& d, const std::vector<Claim>& claims) {
    d.heading(2, "The paper's claims beside our numbers", "claims");
    d.paragraph("Each row: what the paper says (its figure or section), what this run computes, and a plain verdict. A minimum "
                "counts as at the paper's support position when it lies within " + decimals(kPointTolerance, 3) +
                " of it in x0/l (the scan step is about 0.014, the paper reads two decimals). The numbers are also in "
                "`claims.json`.");
    std::vector<std::vector<std::string>> rows;
    int i = 1;
    for (const Claim& c : claims) rows.push_back({std::to_string(i++), c.where, c.paper, c.ours, verdict_name(c.verdict), c.note});
    d.table({"#", "where", "the paper", "this run", "verdict", "note"}, rows, 4);
}

void figures(ReportDocument& d, const std::vector<FigureSpec>& figs) {
    d.heading(2, "Figures", "figures");
    d.paragraph("Each figure as drawn by gnuplot from the CSV beside it (numbered as in the paper; the paper's Fig. 1 is its "
                "sketch of the model). SVG versions and the gnuplot scripts that redraw them are in the same folder. In the "
                "CSVs `nan` marks a value the run does not define (a transient that had not settled by the end of its horizon "
                "has no T_p), and the status columns say why. In a browser each figure is drawn from the same data as an "
                "interactive chart: drag to zoom (double-click to zoom out), hover for values, click a legend entry to hide "
                "or show its curves; the button under a chart shows gnuplot's drawing, which also carries the annotations "
                "(and is what prints).");
    for (const FigureSpec& f : figs) {
        std::vector<std::string> files{f.name + ".svg"};
        for (const auto& dat : f.data) files.push_back(dat.first);
        files.push_back(f.name + ".gp");
        d.figure(f.name, f.title, f.caption, files);
    }
}

void what_was_run(ReportDocument& d, const PaperStudy& st, const ReportRun& run) {
    const PaperStudyOptions& o = st.options;
    const Case& c = o.cases.free_impact;
    d.heading(2, "What was run", "run");
    std::vector<std::vector<std::string>> rows;
    rows.push_back({"program", run.version + "; `" + run.command + "`"});
    rows.push_back({"cases", o.cases.source + ": " + kCantileverFile + " (Figs. 2, 6-8), " + kFreeImpactFile + " (Figs. 3-5, 10, 11), " +
                                 kPrestressFile + " (Fig. 9)"});
    rows.push_back({"beam", "nickel cantilever, l = " + significant(c.beam.length * 1e6, 4) + " um, w = " + significant(c.beam.width * 1e6, 4) + " um, t = " +
                                significant(c.beam.thickness * 1e6, 4) + " um, E = " + significant(c.material.youngs_modulus / 1e9, 4) + " GPa, rho = " +
                                significant(c.material.density, 4) + " kg/m^3, nu = " + significant(c.material.poisson_ratio, 4) +
                                "; clamped at x = 0, free at x = l (the paper's values)"});
    std::string meshes;
    for (int m : o.meshes) meshes += (meshes.empty() ? "" : ", ") + std::to_string(m);
    rows.push_back({"finite elements", "Euler-Bernoulli frame elements, consistent mass; m = " + std::to_string(c.beam.elements) +
                                           " (the paper's mesh) for every figure, and m = " + meshes +
                                           " for the support-position transients of Figs. 4-5"});
    rows.push_back({"first free frequency", "f_1 = " + significant(st.free_modes.result.bending.at(0).frequency_hz / 1e3, 6) + " kHz, omega_1 = " +
                                                significant(st.free_modes.result.bending.at(0).omega, 6) + " rad/s (all tau = omega_1 T)"});
    rows.push_back({"transient solver", "exact event-driven solution (modal exponentials per contact state, events by certified root "
                                        "search; no time step); the scans run without sampled history or energy ledger"});
    const auto positions = scan_positions(o.positions, o.position_min);
    rows.push_back({"support-position transients (Figs. 4, 5, 10)",
                    std::to_string(positions.size()) + " positions per mesh: " + std::to_string(o.positions) + " evenly from x0/l = " +
                        significant(o.position_min, 4) + " to 1 (step " + significant((1.0 - o.position_min) / (o.positions - 1), 3) +
                        ") with 0.67, 0.78, 0.87 added; lift " + significant(st.typical.y0 * 1e6, 4) + " um at the free end, zero gap, horizon " +
                        significant(o.position_horizon * 1e6, 4) + " us"});
    rows.push_back({"supported modes (Figs. 6-8)", std::to_string(st.modal.size()) + " positions x0/l = 1/" + std::to_string(st.modal.size()) +
                                                       " ... 1, support as a pin v(x0) = 0 (the paper's pin joint)"});
    rows.push_back({"prestress (Fig. 9)", std::to_string(st.prestress.points.size()) + " values of Delta/l from 0 to " + significant(o.prestress_max, 4) +
                                              ", support at the free end, lift " +
                                              significant(o.cases.prestress.initial.displacement * 1e6, 4) + " um above the prestressed equilibrium, horizon " +
                                              significant(o.cases.prestress.solver.horizon * 1e6, 4) + " us"});
    std::string forces;
    for (double x : o.force_positions) forces += (forces.empty() ? "" : ", ") + significant(x, 4);
    rows.push_back({"impact force (Fig. 11)", "support at x0/l = " + forces + ", first impact sampled every 2.5 ns"});
    rows.push_back({"threads", std::to_string(st.timing.threads)});
    d.table({"item", "value"}, rows);
}

void timing(ReportDocument& d, const PaperStudy& st, const ReportRun& run) {
    const StudyTiming& t = st.timing;
    d.heading(2, "Timing", "timing");
    d.paragraph("Wall time of this run on " + std::to_string(t.threads) + " thread(s). The study's parts ran as one parallel batch; "
                "their times are CPU seconds summed over threads (thread CPU time, which other work on a shared machine does not "
                "inflate). `vi_bench_paper` times whole runs.");
    d.table({"part", "time"},
            {{"the study (" + std::to_string(t.transients) + " transients and the modal scans), wall", seconds(t.wall_s)},
             {"  Fig. 3 transient (with history), CPU", seconds(t.typical_s)},
             {"  Figs. 4, 5, 10 support-position transients, CPU", seconds(t.position_scans_s)},
             {"  Fig. 9 prestress transients, CPU", seconds(t.prestress_s)},
             {"  Fig. 11 impact forces, CPU", seconds(t.forces_s)},
             {"  modes (Figs. 2, 6-8, ratio peak), CPU", seconds(t.modes_s)},
             {"figures (gnuplot, PNG and SVG), wall", seconds(run.figures_s)},
             {"total before writing the files, wall", seconds(run.total_s)}});
}

}  // namespace

ReportDocument paper_report(const PaperStudy& st, const std::vector<Claim>& claims, const std::vector<FigureSpec>& figs,
                            const ReportRun& run) {
    ReportDocument d;
    d.title = "Ostasevicius et al. (2009) reproduced: vibro-impact of a MEMS cantilever";
    d.heading(1, d.title);
    d.paragraph("This page reproduces the numerical study of section 3 of Ostasevicius et al. (2009), Sensors 9, \"Numerical "
                "analysis of dynamic effects of a nonlinear vibro-impact process for enhancing the reliability of contact-type "
                "MEMS devices\" (Figs. 2-11): a nickel cantilever released onto a Kelvin-Voigt support, bouncing and settling. It "
                "was written by `" + run.command + "` (" + run.version + "); every number on it was computed in that run.");
    summary(d, claims);
    claims_table(d, claims);
    figures(d, figs);
    if (!st.typical.field.frames.empty()) {
        const TypicalTransient& t = st.typical;
        d.animation("beam", "The beam bouncing (Fig. 3's transient)",
                    "The deflection along the beam over the typical transient of Fig. 3, " + std::to_string(t.field.frames.size()) +
                        " frames from t = 0 to " + significant(t.field.frames.back().t * 1e6, 4) + " us (at most " +
                        std::to_string(kMaxPageFrames) + " shown); the dash: the support's surface. `vibroimpact simulate " +
                        kFreeImpactFile + " --field --out DIR` writes the same field for ParaView (field.pvd).",
                    beam_animation_json(t.field, t.surfaces), {});
    }
    what_was_run(d, st, run);
    d.heading(2, "Parameters the paper does not give", "parameters");
    d.paragraph("The paper gives the beam, the material, the mesh and the support positions. It fitted its contact stiffness and "
                "damping to a measured trajectory but does not publish them, nor its Rayleigh damping ratios, the lift, the "
                "horizon, or how impacts and the end of the transient are delimited. " +
                (st.options.cases.source.rfind("built-in", 0) == 0
                     ? std::string("The values used are our choice, not the paper's and not fitted (docs/paper-parameters.md "
                                   "shows the contact-stiffness scan behind Kc):")
                     : "The values used are those chosen in the case files of " + st.options.cases.source +
                           " (`--examples`), not the paper's and not fitted; the reasons given are those of the built-in "
                           "examples, evaluated at these values:"));
    d.table({"parameter", "value", "why"}, unstated_parameters(st));
    timing(d, st, run);
    return d;
}

std::string claims_json(const std::vector<Claim>& claims) {
    nlohmann::json out = nlohmann::json::array();
    for (const Claim& c : claims) {
        nlohmann::json values = nlohmann::json::object();
        for (const auto& [k, v] : c.values) values[k] = v;
        out.push_back({{"id", c.id}, {"where", c.where}, {"paper", c.paper}, {"ours", c.ours}, {"verdict", verdict_name(c.verdict)},
                       {"note", c.note}, {"values", values}});
    }
    return out.dump(2) + "\n";
}

OutputFiles paper_output_files(const PaperStudy& st, const std::vector<Claim>& claims, const std::vector<FigureSpec>& figs,
                               const std::vector<RenderedFigure>& rendered, const ReportRun& run) {
    std::map<std::string, std::string> png;
    OutputFiles files = figure_files(figs, rendered, &png);
    const ReportDocument doc = paper_report(st, claims, figs, run);
    files["report.html"] = render_html(doc, png, figure_charts(figs));
    files["report.md"] = render_markdown(doc);
    files["claims.json"] = claims_json(claims);
    return files;
}

}  // namespace vi
