// The switch study: run pull-in and the transient, and write the page with its files.

#include "study/switch/switch_study.hpp"

#include <chrono>
#include <cstdio>
#include <map>

#include "model/input_error.hpp"
#include "model/run_estimate.hpp"
#include "model/run_control.hpp"
#include "plot/beam_animation.hpp"
#include "plot/chart_json.hpp"
#include "report/field_output.hpp"
#include "report/pullin_output.hpp"
#include "report/transient_output.hpp"
#include "model/number_format.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

// Where each support's surface is: [x (m), height (m)], for the animated beam.
std::vector<std::pair<double, double>> support_surfaces(const Case& c) {
    std::vector<std::pair<double, double>> out;
    for (const Support& k : c.supports) out.emplace_back(k.position * c.beam.length, k.surface);
    return out;
}

std::string beam_caption(const BeamField& f) {
    return "The deflection along the beam (the whole field, " + std::to_string(f.frames.size()) +
           " frames from t = 0 to " + formatted("%.4g us", f.frames.back().t * 1e6) +
           ", at most " + std::to_string(kMaxPageFrames) + " shown); the dashes: the supports' surfaces. The same "
           "field is in field.pvd (ParaView) and field.csv.";
}

std::string volts(const std::optional<double>& v) { return v ? formatted("%.4g V", *v) : std::string("none"); }

std::vector<std::vector<std::string>> pullin_rows(const SwitchStudy& s) {
    const PullinResult& r = s.pullin;
    const auto point = [](const std::optional<PullinPoint>& p) {
        return p ? std::vector<std::string>{formatted("%.5g", p->voltage), formatted("%.4g", p->watched_travel * 1e6),
                                            formatted("%.4g", p->travel * 1e6), formatted("%.4g", p->capacitance * 1e15)}
                 : std::vector<std::string>{"-", "-", "-", "-"};
    };
    std::vector<std::vector<std::string>> rows;
    const auto add = [&](const char* what, const std::optional<PullinPoint>& p) {
        std::vector<std::string> row{what};
        const std::vector<std::string> cells = point(p);
        row.insert(row.end(), cells.begin(), cells.end());
        rows.push_back(std::move(row));
    };
    add("pull-in (fold of the open branch)", r.pullin);
    add("touch-down on a support", r.touchdown);
    add("collapse of the closed switch", r.collapse);
    rows.push_back({"release (pull-out)", r.release_voltage ? formatted("%.5g", *r.release_voltage) : "-", "-", "-", "-"});
    return rows;
}

std::vector<std::vector<std::string>> episode_rows(const SwitchStudy& s) {
    std::vector<std::vector<std::string>> rows;
    const std::vector<ContactEpisode>& e = s.transient.result.episodes;
    for (std::size_t k = 0; k < e.size(); ++k) {
        const ContactEpisode& x = e[k];
        const std::string& contact = s.transient.built.model.contacts.at(static_cast<std::size_t>(x.support)).name;
        rows.push_back({std::to_string(k + 1), contact, formatted("%.5g", x.t_on * 1e6),
                        x.closed_at_end ? "closed at the end" : formatted("%.5g", x.t_off * 1e6), formatted("%.4g", x.v_in),
                        formatted("%.4g", x.peak_force * 1e6), formatted("%.4g", x.peak_penetration * 1e9)});
    }
    return rows;
}

}  // namespace

SwitchStudy run_switch_study(const Case& c) {
    if (c.electrodes.empty()) throw InputError("electrodes: the case has no [[electrodes]] (a switch report needs one)");
    // Both parts' limits before either runs: the transient's (check_transient_run) would otherwise
    // come only after the pull-in trace.
    const auto limits = check_transient_run(c, true, memory_budget_bytes());
    if (!limits.empty()) throw InputError(limits.front().key + ": " + limits.front().message);
    SwitchStudy s;
    s.c = c;
    auto t0 = std::chrono::steady_clock::now();
    s.pullin = trace_pullin(c);
    s.pullin_s = seconds_since(t0);
    check_run();
    t0 = std::chrono::steady_clock::now();
    SimulationOptions o;
    o.field = true;  // the page's animated beam
    s.transient = run_simulation(c, o);
    s.transient_s = seconds_since(t0);
    return s;
}

ReportDocument switch_report(const SwitchStudy& s, const std::string& command) {
    ReportDocument d;
    d.title = "Switch report: " + s.c.name;
    d.heading(1, d.title);
    d.paragraph("Made by `" + command + "` from `" + s.c.origin.file + "`: the static pull-in of the beam under its "
                "electrodes (all at one voltage) and the case's own transient. Model, definitions and validation: "
                "docs/electrostatics.md.");
    d.heading(2, "Static pull-in", "pullin");
    d.table({"state", "voltage [V]", "watched point travel [um]", "mean travel [um]", "capacitance [fF]"}, pullin_rows(s));
    d.paragraph("Branch ends: " + s.pullin.end + ". Traced in " + formatted("%.3f", s.pullin_s) + " s (" +
                std::to_string(s.pullin.branch.size()) + " points, " + std::to_string(s.pullin.newton_iterations) +
                " Newton iterations).");
    d.figure("switch_pullin", "Voltage against travel", "", {"switch_pullin.csv", "switch_pullin.gp"});
    d.figure("switch_cv", "C-V", "", {"switch_cv.csv", "switch_cv.gp"});
    d.figure("switch_fv", "f-V", "", {"switch_fv.csv", "switch_fv.gp"});

    const ImpactSummary& sum = s.transient.summary;
    const TransientResult& r = s.transient.result;
    d.heading(2, "Switching transient", "transient");
    const Electrode& e = s.c.electrodes.front();
    std::vector<std::string> facts{
        "electrodes[0]: " + formatted("%.4g V", e.voltage) + " amplitude; horizon " + formatted("%.4g us", r.t_end * 1e6) + "; " +
            std::to_string(r.episodes.size()) + " contact episodes in " + std::to_string(sum.impacts.size()) + " impacts",
        "first contact (closing time): " + (r.episodes.empty() ? std::string("none") : formatted("%.5g us", r.episodes.front().t_on * 1e6)),
        "T_p: " + (sum.Tp ? formatted("%.5g us", *sum.Tp * 1e6) : std::string("none")) + " (" + sum.Tp_reason + ")",
        "static pull-in for comparison: " + volts(s.pullin.pullin ? std::optional<double>(s.pullin.pullin->voltage) : std::nullopt),
        "solver: " + r.stats.method + ", " + std::to_string(r.stats.steps) + " steps, " + formatted("%.3f", s.transient_s) + " s"};
    d.list(facts);
    if (s.transient.switching) {
        const SwitchingLedger& w = *s.transient.switching;
        const auto us = [](const std::optional<double>& t) { return t ? formatted("%.5g us", *t * 1e6) : std::string("-"); };
        d.heading(3, "Switching ledger");
        d.table({"closing time", "bounces", "stable contact from", "peak contact force [uN]", "release time", "state"},
                {{us(w.closing_time), bounce_text(w), us(w.stable_contact), formatted("%.4g", w.peak_force * 1e6),
                  us(w.release_time), w.state}});
        d.paragraph(w.reason);
    }
    d.heading(3, "Bounce ledger: every contact episode");
    d.table({"episode", "support", "onset [us]", "end [us]", "impact velocity [m/s]", "peak force [uN]",
             "peak penetration [nm]"},
            episode_rows(s));
    d.figure("switch_transient", "Switching transient", "", {"switch_transient.csv", "switch_transient.gp"});
    const BeamField field = beam_field(s.transient.built.model.system, s.transient.result.history);
    if (!field.frames.empty()) {
        d.animation("switch_beam", "The beam moving", beam_caption(field), beam_animation_json(field, support_surfaces(s.c)),
                    {"field.pvd", "field.csv"});
    }
    d.heading(2, "Files", "files");
    d.list({"`pullin.json`, `pullin_branch.csv`, `pullin_frequencies.csv`: the pull-in trace (as `vibroimpact pullin --out`)",
            "`summary.json`, `history.csv`, `events.csv`: the transient (as `vibroimpact simulate --out`)",
            "`switch_*.csv` and `switch_*.gp`: each figure's data and its gnuplot script (`gnuplot switch_pullin.gp` redraws it)"});
    return d;
}

OutputFiles switch_report_files(const SwitchStudy& s, const std::vector<FigureSpec>& figures,
                                const std::vector<RenderedFigure>& rendered, const std::string& command) {
    OutputFiles files = pullin_files(s.pullin);
    const OutputFiles transient = transient_files(s.c, s.transient.built, s.transient.result, s.transient.summary);
    files.insert(transient.begin(), transient.end());
    files.merge(field_files(beam_field(s.transient.built.model.system, s.transient.result.history)));
    std::map<std::string, std::string> png;
    const OutputFiles drawn = figure_files(figures, rendered, &png);
    files.insert(drawn.begin(), drawn.end());
    ReportDocument doc = switch_report(s, command);
    // The captions live with the figures: fill them into the page's figure blocks.
    for (const FigureSpec& f : figures) {
        for (ReportBlock& b : doc.blocks) {
            if (b.kind == ReportBlock::Kind::figure && b.figure == f.name) b.caption = f.caption;
        }
    }
    files["report.html"] = render_html(doc, png, figure_charts(figures));
    files["report.md"] = render_markdown(doc);
    return files;
}

}  // namespace vi
