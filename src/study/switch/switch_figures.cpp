// The switch report's figures: the pull-in curve, C-V, f-V and the switching transient.

#include <algorithm>
#include <limits>
#include <optional>
#include <sstream>

#include "io/csv_names.hpp"
#include "io/csv_writer.hpp"
#include "study/switch/switch_study.hpp"

namespace vi {
namespace {

constexpr const char* kGrid = "set grid lc rgb '#dddddd'\nset key top left\n";

// The equilibria as CSV: stable and unstable points in separate columns so that gnuplot draws the
// unstable branch dashed.
std::string branch_csv(const PullinResult& r) {
    CsvTable t;
    t.header = {"watched_travel_um", "mean_travel_um", "voltage_stable_v", "voltage_unstable_v", "capacitance_ff", "contact"};
    for (const PullinPoint& p : r.branch) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        t.add_row({csv_number(p.watched_travel * 1e6), csv_number(p.travel * 1e6), csv_number(p.stable ? p.voltage : nan),
                   csv_number(p.stable ? nan : p.voltage), csv_number(p.capacitance * 1e15), csv_flag(p.contact)});
    }
    return t.str();
}

ChartSeries chart_series(std::string label, std::string x, std::string y, std::string colour, bool dashed) {
    ChartSeries c;
    c.label = std::move(label);
    c.x = std::move(x);
    c.y = std::move(y);
    c.color = std::move(colour);
    c.dashed = dashed;
    return c;
}

std::string marker(int id, const char* what, const PullinPoint& p, double x_um, const char* colour) {
    std::ostringstream s;
    s << "set label " << id << " sprintf('" << what << " %.2f V', " << p.voltage << ") at first " << x_um << ", first "
      << p.voltage << " point pointtype 7 pointsize 1.2 lc rgb '" << colour << "' offset 1,-0.2 textcolor rgb '" << colour << "'\n";
    return s.str();
}

FigureSpec pullin_figure(const SwitchStudy& s) {
    const PullinResult& r = s.pullin;
    FigureSpec f;
    f.name = "switch_pullin";
    f.title = "Static pull-in: voltage against travel";
    f.caption = "Equilibria traced by displacement control (vibroimpact pullin): the voltage that holds the beam at each "
                "travel of the watched point (x/l = " + gp_number(r.watched_x) +
                ") toward the electrode, stable (solid) and unstable (dashed). Pull-in is the fold of the open branch; "
                "after touch-down the contact holds the beam; release is the lowest voltage of a stable closed state.";
    f.data = {{"switch_pullin.csv", branch_csv(r)}};
    std::ostringstream p;
    p << kGrid << "set xlabel 'travel of the watched point toward the electrode  [μm]'\nset ylabel 'voltage  [V]'\n";
    int id = 1;
    if (r.pullin) p << marker(id++, "pull-in", *r.pullin, r.pullin->watched_travel * 1e6, "#d62728");
    if (r.touchdown) p << marker(id++, "touch-down", *r.touchdown, r.touchdown->watched_travel * 1e6, "#2ca02c");
    if (r.collapse) p << marker(id++, "collapse", *r.collapse, r.collapse->watched_travel * 1e6, "#9467bd");
    p << "plot 'switch_pullin.csv' using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'stable', "
         "'' using 1:4 with lines lw 2 dt 2 lc rgb '#ff7f0e' title 'unstable'\n";
    f.plot = p.str();
    ChartPanel c;
    c.x_label = "travel of the watched point toward the electrode [μm]";
    c.y_label = "voltage [V]";
    c.series = {chart_series("stable", "watched_travel_um", "voltage_stable_v", "#1f77b4", false),
                chart_series("unstable", "watched_travel_um", "voltage_unstable_v", "#ff7f0e", true)};
    f.charts = {c};
    return f;
}

FigureSpec cv_figure(const SwitchStudy& s) {
    FigureSpec f;
    f.name = "switch_cv";
    f.title = "Capacitance against voltage";
    f.caption = "Capacitance of all electrodes along the traced equilibria (stable solid, unstable dashed): the C-V "
                "curve a capacitance meter sees on the way up to pull-in, and the closed state's.";
    f.data = {{"switch_cv.csv", branch_csv(s.pullin)}};
    f.plot = std::string(kGrid) + "set xlabel 'voltage  [V]'\nset ylabel 'capacitance  [fF]'\n"
             "plot 'switch_cv.csv' using 3:5 with lines lw 2 lc rgb '#1f77b4' title 'stable', "
             "'' using 4:5 with lines lw 2 dt 2 lc rgb '#ff7f0e' title 'unstable'\n";
    ChartPanel c;
    c.x_label = "voltage [V]";
    c.y_label = "capacitance [fF]";
    c.series = {chart_series("stable", "voltage_stable_v", "capacitance_ff", "#1f77b4", false),
                chart_series("unstable", "voltage_unstable_v", "capacitance_ff", "#ff7f0e", true)};
    f.charts = {c};
    return f;
}

FigureSpec fv_figure(const SwitchStudy& s) {
    const PullinResult& r = s.pullin;
    CsvTable t;
    std::size_t modes = 0;
    for (const PullinFrequencies& x : r.frequencies) modes = std::max(modes, x.frequency_hz.size());
    t.header = {"voltage_v"};
    for (std::string& name : numbered_columns("f", modes, "_khz")) t.header.push_back(std::move(name));
    for (const PullinFrequencies& x : r.frequencies) {
        std::vector<CsvCell> row{csv_number(x.voltage)};
        for (std::size_t k = 0; k < modes; ++k) {
            row.push_back(k < x.frequency_hz.size() ? csv_number(x.frequency_hz[k] * 1e-3) : csv_missing());
        }
        t.add_row(row);
    }
    FigureSpec f;
    f.name = "switch_fv";
    f.title = "Natural frequencies against DC bias";
    f.caption = "The lowest bending frequencies about the stable open equilibria up to pull-in: electrostatic softening "
                "pulls the first toward zero at V_PI.";
    f.data = {{"switch_fv.csv", t.str()}};
    std::ostringstream p;
    p << kGrid << "set key top right\nset xlabel 'DC bias  [V]'\nset ylabel 'frequency  [kHz]'\nset logscale y\n";
    if (modes == 0) {
        p << "set label 1 'no stable open equilibria' at graph 0.5, graph 0.5 center\nplot [0:1] [1:10] NaN notitle\n";
    } else {
        p << "plot ";
        for (std::size_t k = 0; k < modes; ++k) {
            p << (k ? ", " : "") << "'switch_fv.csv' using 1:" << k + 2 << " with linespoints lw 2 pt 7 ps 0.6 title 'f_" << k + 1
              << "'";
        }
        p << "\n";
    }
    f.plot = p.str();
    ChartPanel c;
    c.x_label = "DC bias [V]";
    c.y_label = "frequency [kHz]";
    c.log_y = true;
    for (std::size_t k = 0; k < modes; ++k) {
        ChartSeries m = chart_series("f_" + std::to_string(k + 1), "voltage_v", t.header[k + 1], "", false);
        m.style = ChartSeries::Style::linespoints;
        c.series.push_back(m);
    }
    f.charts = {c};
    return f;
}

FigureSpec transient_figure(const SwitchStudy& s) {
    const TimeHistory& h = s.transient.result.history;
    const Electrode& e = s.c.electrodes.front();
    CsvTable t;
    t.header = {"t_us", "watched_um", "contact_force_un", "voltage_v"};
    double v_min = 0.0, v_max = 0.0;
    for (std::size_t i = 0; i < h.t.size(); ++i) {
        double force = 0.0;
        for (const auto& f : h.contact_force) force += f[i];
        const double v = e.voltage * e.time(h.t[i]);
        v_min = std::min(v_min, v);
        v_max = std::max(v_max, v);
        t.add_row({h.t[i] * 1e6, h.watched_v[i] * 1e6, force * 1e6, v});
    }
    // The voltage axis starts at 0 on the side the drive never crosses (a negative drive pulls as a
    // positive one does; a fixed [0:*] would leave gnuplot no point to draw); all at 0: autoscaled.
    const char* y2range = v_min < 0.0 ? (v_max > 0.0 ? "[*:*]" : "[*:0]") : (v_max > 0.0 ? "[0:*]" : "[*:*]");
    FigureSpec f;
    f.name = "switch_transient";
    f.title = "Switching transient";
    f.caption = "The case's transient (vibroimpact simulate): (a) the watched point's displacement with the contact "
                "episodes shaded and the voltage of electrodes[0]; (b) the total contact force.";
    f.data = {{"switch_transient.csv", t.str()}};
    f.height = 760;
    std::ostringstream p;
    // Fixed margins: both panels share the time axis, though only (a) has a right-hand axis.
    p << "set multiplot layout 2,1\n" << kGrid << "set xlabel 't  [μs]'\nset lmargin 10\nset rmargin 10\n";
    int obj = 1;
    for (const ContactEpisode& c : s.transient.result.episodes) {
        if (obj > 200) break;  // a chattering run would bury the curve under its shading
        p << "set object " << obj++ << " rect from first " << c.t_on * 1e6 << ", graph 0 to first " << c.t_off * 1e6
          << ", graph 1 fillcolor rgb '#e8e8e8' fillstyle solid noborder behind\n";
    }
    p << "set ylabel 'displacement  [μm]'\nset y2label 'voltage  [V]'\nset y2tics\nset ytics nomirror\nset y2range "
      << y2range << "\nset title '(a) watched point (x/l = " << gp_number(s.pullin.watched_x) << ") and voltage'\n"
         "plot 'switch_transient.csv' using 1:2 with lines lw 1.5 lc rgb '#1f77b4' title 'displacement', "
         "'' using 1:4 axes x1y2 with lines lw 1 dt 2 lc rgb '#7f7f7f' title 'voltage'\n"
         "unset object\nunset y2label\nunset y2tics\nset ytics mirror\n"
         "set title '(b) contact force'\nset ylabel 'force  [μN]'\n"
         "plot 'switch_transient.csv' using 1:3 with lines lw 1.5 lc rgb '#d62728' notitle\nunset multiplot\n";
    f.plot = p.str();
    ChartPanel a;
    a.title = "(a) watched point (x/l = " + gp_number(s.pullin.watched_x) + ") and voltage; grey: in contact";
    a.x_label = "t [μs]";
    a.y_label = "displacement [μm]";
    a.y2_label = "voltage [V]";
    for (const ContactEpisode& c : s.transient.result.episodes) a.x_bands.emplace_back(c.t_on * 1e6, c.t_off * 1e6);
    ChartSeries v = chart_series("voltage", "t_us", "voltage_v", "#7f7f7f", true);
    v.right_axis = true;
    a.series = {chart_series("displacement", "t_us", "watched_um", "#1f77b4", false), v};
    ChartPanel b;
    b.title = "(b) contact force";
    b.x_label = a.x_label;
    b.y_label = "force [μN]";
    b.x_bands = a.x_bands;
    b.series = {chart_series("contact force", "t_us", "contact_force_un", "#d62728", false)};
    f.charts = {a, b};
    return f;
}

}  // namespace

std::vector<FigureSpec> switch_figures(const SwitchStudy& s) {
    return {pullin_figure(s), cv_figure(s), fv_figure(s), transient_figure(s)};
}

}  // namespace vi
