// Figs. 3, 4, 5, 9, 10 and 11: the free-impact transients.

#include <algorithm>
#include <cmath>
#include <sstream>

#include "study/paper/curve_features.hpp"
#include "study/paper/claims.hpp"
#include "io/csv_writer.hpp"
#include "study/paper/figures.hpp"

namespace vi::figure_detail {



// "; 3 positions failed (first: reason)" or "" when every run succeeded.
std::string failures(const TransientScan& s) {
    int n = 0;
    std::string first;
    for (const TransientPoint& p : s.points) {
        if (p.ok()) continue;
        if (n++ == 0) first = p.error;
    }
    if (n == 0) return "";
    std::string out = " ";  // built step by step: GCC 12 warns (-Wrestrict) on one long chain of +
    out += std::to_string(n);
    out += " runs failed (gaps; first reason: ";
    out += first;
    out += ").";
    return out;
}

int unsettled(const TransientScan& s) {
    return static_cast<int>(std::count_if(s.points.begin(), s.points.end(), [](const TransientPoint& p) { return p.ok() && !p.tau_p; }));
}

CsvCell status(const TransientPoint& p) { return csv_text(p.ok() ? p.tp_reason : "error: " + p.error); }

std::string mesh_prefix(int elements) { return "m" + std::to_string(elements) + "_"; }

FigureSpec fig3(const PaperStudy& st) {
    const TypicalTransient& t = st.typical;
    const ImpactSummary& s = t.summary;
    CsvTable h;
    h.header = {"t_us", "tip_nm"};
    for (std::size_t i = 0; i < t.t.size(); ++i) h.add_row({t.t[i] * 1e6, (t.tip[i] - t.tip_equilibrium) * 1e9});
    CsvTable im;
    im.header = {"impact", "t_on_us", "t_off_us", "episodes", "v_in_m_s", "peak_force_un"};
    for (std::size_t i = 0; i < s.impacts.size(); ++i) {
        const Impact& a = s.impacts[i];
        im.add_row({csv_count(static_cast<std::int64_t>(i + 1)), csv_number(a.t_on * 1e6), csv_number(a.t_off * 1e6),
                    csv_count(a.episodes), csv_number(a.v_in), csv_number(a.peak_force * 1e6)});
    }
    const double y_max_nm = s.y_max ? *s.y_max * 1e9 : 0.0;
    // When the largest rebound happens (to the output step), for the arrow in panel (b).
    double t_ymax = 0.0, highest = -1e300;
    for (std::size_t i = 0; i < t.t.size(); ++i) {
        if (s.impacts.empty() || t.t[i] < s.impacts.front().t_on) continue;
        if (t.tip[i] > highest) {
            highest = t.tip[i];
            t_ymax = t.t[i] * 1e6;
        }
    }
    const double y0_nm = t.y0 * 1e9;
    std::ostringstream p;
    p << "set multiplot layout 2,1 title 'A typical free impact transient: support at the free end, lift y_0 = " << significant(y0_nm / 1e3, 4)
      << " μm' font ',13'\nset grid lc rgb '#dddddd'\nset key top right\nset xzeroaxis lt -1\n"
      << "set ylabel 'free-end displacement y  [nm]'\nset xlabel 't  [μs]'\n";
    p << "set title '(a) the whole transient'\nset xrange [0:" << (t.t.empty() ? 1.0 : t.t.back() * 1e6) << "]\n";
    if (s.Tp) {
        p << "set arrow 1 from first " << *s.Tp * 1e6 << ", graph 0 to first " << *s.Tp * 1e6
          << ", graph 1 nohead dashtype 2 linewidth 1.5 linecolor rgb '#d62728'\n"
          << "set label 1 sprintf('T_p = %.1f μs (τ_p = %.1f)', " << *s.Tp * 1e6 << ", " << *s.Tp * t.omega1 << ") at first "
          << *s.Tp * 1e6 << ", graph 0.9 left offset 0.5,0 textcolor rgb '#d62728'\n";
    }
    if (s.y_max) {
        p << "set arrow 2 from graph 0, first " << y_max_nm << " to graph 1, first " << y_max_nm
          << " nohead dashtype 3 linecolor rgb '#2ca02c'\n"
          << "set label 2 sprintf('y_{max} = %.1f nm (z_{max} = %.2e)', " << y_max_nm << ", " << *s.z_max << ") at graph 0.7, first "
          << y_max_nm << " offset 0,0.7 textcolor rgb '#2ca02c'\n";
    }
    p << "plot 'fig3.csv' using 1:2 with lines linewidth 1.2 linecolor rgb '#1f77b4' title 'free end'\n";
    p << "unset arrow\nunset label\n";
    // (b): the first cycles with T, T1, T2 and the grey contact intervals.
    if (s.impacts.size() >= 2) {
        const Impact& a = s.impacts[0];
        const Impact& b = s.impacts[1];
        const double end = std::min(b.t_off + 0.6 * (b.t_on - a.t_on), st.typical.t.empty() ? b.t_off : st.typical.t.back()) * 1e6;
        p << "set title '(b) the first cycles: T, T_1, T_2 and the rebound y_{max}'\nset xrange [0:" << end << "]\n";
        int obj = 1;
        for (const Impact& c : s.impacts) {
            if (c.t_on * 1e6 > end) break;
            p << "set object " << obj++ << " rect from first " << c.t_on * 1e6 << ", graph 0 to first " << c.t_off * 1e6
              << ", graph 1 fillcolor rgb '#e8e8e8' fillstyle solid noborder behind\n";
        }
        const double top = y0_nm * 1.25, mid = -y0_nm * 0.35, low = -y0_nm * 0.65;
        p << "set yrange [" << -y0_nm * 0.85 << ":" << y0_nm * 1.45 << "]\n";
        auto span = [&](int id, double from, double to, double y, const std::string& text) {
            p << "set arrow " << id << " from first " << from << ", first " << y << " to first " << to << ", first " << y
              << " heads size screen 0.006,90 linewidth 1.5 linecolor rgb 'black'\n"
              << "set label " << id << " '" << text << "' at first " << 0.5 * (from + to) << ", first " << y
              << " center offset 0,0.8 font ',10'\n";
        };
        span(1, a.t_on * 1e6, b.t_on * 1e6, top, "T = " + us(b.t_on - a.t_on) + " μs");
        span(2, a.t_off * 1e6, b.t_on * 1e6, mid, "T_1 = " + us(b.t_on - a.t_off) + " μs");
        span(3, a.t_on * 1e6, a.t_off * 1e6, low, "T_2 = " + us(a.t_off - a.t_on) + " μs");
        if (s.y_max && t_ymax > 0.0 && t_ymax < end) {
            p << "set arrow 4 from first " << t_ymax << ", first 0 to first " << t_ymax << ", first " << y_max_nm
              << " heads size screen 0.006,90 linewidth 1.5 linecolor rgb '#2ca02c'\n"
              << "set label 4 'y_{max}' at first " << t_ymax << ", first " << 0.5 * y_max_nm
              << " left offset 0.6,0 textcolor rgb '#2ca02c' font ',10'\n";
        }
        p << "plot 'fig3.csv' using 1:2 with lines linewidth 1.5 linecolor rgb '#1f77b4' title 'free end (grey: in contact)'\n";
    }
    p << "unset multiplot\n";
    std::string text = "The free end of the paper's cantilever, lifted " + significant(y0_nm / 1e3, 4) +
                       " um by a static tip force and released onto a support at its free end (zero gap; Kc and Cc in the "
                       "parameter table), relative to its final equilibrium. First cycle: T = " +
                       (s.T_first ? us(*s.T_first) : "n/a") + " us, T1 = " + (s.T1_first ? us(*s.T1_first) : "n/a") +
                       " us, T2 = " + (s.T2_first ? us(*s.T2_first) : "n/a") + " us; T_p = " + (s.Tp ? us(*s.Tp) + " us (" + s.Tp_reason + ")" : "not reached (" + s.Tp_reason + ")") +
                       "; " + std::to_string(s.impacts.size()) + " impacts. The paper gives T = 5.1 us (see the claims). Sampled every " +
                       significant(t.output_step * 1e9, 3) + " ns; events and y_max are located exactly, not sampled.";
    FigureSpec fig{"fig3", "Fig. 3: a typical free impact transient", text,
                   {{"fig3.csv", h.str()}, {"fig3_impacts.csv", im.str()}}, p.str(), 1100, 900, 1.0, {}};
    // (a) the whole transient, (b) the first cycles; grey: in contact; dashed: T_p.
    for (const bool first_cycles : {false, true}) {
        ChartPanel c;
        c.title = first_cycles ? "(b) the first cycles (double-click: the whole transient)" : "(a) the whole transient";
        c.x_label = "t [μs]";
        c.y_label = "free-end displacement y [nm]";
        for (const Impact& a : s.impacts) c.x_bands.emplace_back(a.t_on * 1e6, a.t_off * 1e6);
        if (s.Tp) c.x_marks.push_back(*s.Tp * 1e6);
        if (first_cycles && s.impacts.size() >= 2) {
            const Impact& a = s.impacts[0];
            const Impact& b = s.impacts[1];
            c.x_min = 0.0;
            c.x_max = std::min(b.t_off + 0.6 * (b.t_on - a.t_on), t.t.empty() ? b.t_off : t.t.back()) * 1e6;
        } else if (first_cycles) {
            continue;
        }
        c.series.push_back(series("free end", "t_us", "tip_nm", ChartSeries::Style::lines, "#1f77b4"));
        fig.charts.push_back(c);
    }
    return fig;
}

FigureSpec fig4(const PaperStudy& st) {
    CsvTable t;
    t.header = {"x0_over_l"};
    for (const TransientScan& s : st.position_scans) {
        for (const char* c : {"z_max", "z_min", "status"}) t.header.push_back(mesh_prefix(s.elements) + c);
    }
    const std::size_t n = st.position_scans.empty() ? 0 : st.position_scans.front().points.size();
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<CsvCell> row{csv_number(st.position_scans.front().points[i].x)};
        for (const TransientScan& s : st.position_scans) {
            const TransientPoint& p = s.points[i];
            row.push_back(csv_number(p.z_max));
            row.push_back(csv_number(p.z_min));
            row.push_back(status(p));
        }
        t.add_row(row);
    }
    std::ostringstream p;
    p << colors_command() << "set grid lc rgb '#dddddd'\nset key bottom right\nset xzeroaxis lt -1\n" << particular_points()
      << scan_xrange(st)
      << "set title 'Rebound z_{max} and free-end deflection during impact against the support position' font ',13'\n"
      << "set xlabel 'support position x_0/l  [-]'\nset ylabel 'z = y/l  [10^{-3}]'\n";
    std::string cmd = "plot ";
    for (std::size_t k = 0; k < st.position_scans.size(); ++k) {
        const std::string m = std::to_string(st.position_scans[k].elements);
        const std::size_t col = 2 + 3 * k;
        const std::string style = k == 0 ? "linespoints pointtype 7 pointsize 0.6 linewidth 2" : "lines dashtype 2 linewidth 2";
        p << cmd << "'fig4.csv' using 1:($" << col << "*1e3) with " << style << " linecolor rgb word(colors," << k + 1
          << ") title 'z_{max}, m = " << m << "', \\\n  'fig4.csv' using 1:($" << col + 1 << "*1e3) with " << style
          << " linecolor rgb word(colors," << k + 3 << ") title 'free end during impact, m = " << m << "'";
        cmd = ", \\\n  ";
    }
    p << "\n";
    std::string caption = "Largest rebound of the free end above its equilibrium, z_max = y_max/l (upper curves), and its deepest "
                          "deflection while the beam is in contact (lower curves), as the support moves along the beam; lift " +
                          significant(st.typical.y0 * 1e6, 4) + " um at the free end, zero gap, Kc and Cc fixed. " +
                          std::to_string(n) + " positions per mesh.";
    for (const TransientScan& s : st.position_scans) caption += failures(s);
    FigureSpec fig{"fig4", "Fig. 4: rebound against support position", caption, {{"fig4.csv", t.str()}}, p.str(), 1000, 620, 1.0, {}};
    ChartPanel c;
    c.x_label = "support position x0/l [-]";
    c.y_label = "z = y/l [10⁻³]";
    c.x_marks = particular_marks();
    for (std::size_t k = 0; k < st.position_scans.size(); ++k) {
        const std::string m = std::to_string(st.position_scans[k].elements);
        const int kk = static_cast<int>(k);
        for (const bool during : {false, true}) {
            ChartSeries s = series(during ? "free end during impact, m = " + m : "z_max, m = " + m, "x0_over_l",
                                   mesh_prefix(st.position_scans[k].elements) + (during ? "z_min" : "z_max"),
                                   k == 0 ? ChartSeries::Style::linespoints : ChartSeries::Style::lines, color(kk + (during ? 3 : 1)));
            s.y_scale = 1e3;
            s.dashed = k > 0;
            c.series.push_back(s);
        }
    }
    fig.charts.push_back(c);
    return fig;
}

FigureSpec fig5(const PaperStudy& st) {
    CsvTable t;
    t.header = {"x0_over_l"};
    for (const TransientScan& s : st.position_scans) {
        t.header.push_back(mesh_prefix(s.elements) + "tau_p");
        t.header.push_back(mesh_prefix(s.elements) + "tp_reason");
    }
    if (!st.position_scans.empty()) {
        for (const char* c : {"tau", "tau1", "tau2"}) t.header.push_back(mesh_prefix(st.position_scans.front().elements) + c);
    }
    const std::size_t n = st.position_scans.empty() ? 0 : st.position_scans.front().points.size();
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<CsvCell> row{csv_number(st.position_scans.front().points[i].x)};
        for (const TransientScan& s : st.position_scans) {
            row.push_back(csv_number(s.points[i].tau_p));
            row.push_back(status(s.points[i]));
        }
        const TransientPoint& r = st.position_scans.front().points[i];
        row.push_back(csv_number(r.tau));
        row.push_back(csv_number(r.tau1));
        row.push_back(csv_number(r.tau2));
        t.add_row(row);
    }
    const std::size_t ns = st.position_scans.size();
    std::ostringstream p;
    p << colors_command() << "set multiplot layout 2,1 title 'Temporal characteristics against the support position (τ = ω_1 T)' font ',13'\n"
      << "set grid lc rgb '#dddddd'\nset key top right\n" << particular_points() << scan_xrange(st)
      << "set xlabel 'support position x_0/l  [-]'\n"
      << "set ylabel 'τ_p = ω_1 T_p  [-]'\nset title '(a) duration of the transient (gaps: not settled within the horizon)'\n";
    std::string cmd = "plot ";
    for (std::size_t k = 0; k < ns; ++k) {
        const TransientScan& s = st.position_scans[k];
        const std::string style = k == 0 ? "linespoints pointtype 7 pointsize 0.6 linewidth 2" : "linespoints pointtype 6 pointsize 0.6 dashtype 2 linewidth 1.5";
        p << cmd << "'fig5.csv' using 1:" << 2 + 2 * k << " with " << style << " linecolor rgb word(colors," << k + 1 << ") title 'τ_p, m = "
          << s.elements << " (" << unsettled(s) << " of " << s.points.size() << " not settled)'";
        cmd = ", \\\n  ";
    }
    const std::size_t c0 = 2 + 2 * ns;
    p << "\nset title '(b) period τ, flight τ_1 and impact τ_2 of the first cycle, m = "
      << (ns ? std::to_string(st.position_scans.front().elements) : std::string("?")) << "'\nset ylabel 'τ, τ_1, τ_2  [-]'\n"
      << "plot 'fig5.csv' using 1:" << c0 << " with linespoints pointtype 7 pointsize 0.5 linewidth 2 linecolor rgb word(colors,3) title 'τ', \\\n"
      << "  'fig5.csv' using 1:" << c0 + 1 << " with linespoints pointtype 5 pointsize 0.5 linewidth 2 linecolor rgb word(colors,4) title 'τ_1', \\\n"
      << "  'fig5.csv' using 1:" << c0 + 2 << " with linespoints pointtype 9 pointsize 0.5 linewidth 2 linecolor rgb word(colors,5) title 'τ_2'\n"
      << "unset multiplot\n";
    std::string caption = "Dimensionless duration of the transient tau_p = omega_1 T_p (a) and the first cycle's tau, tau_1, tau_2 (b) "
                          "as the support moves. T_p ends at the last impact whose penetration exceeds 1 % of the first one's; "
                          "where the bouncing had not settled by the end of the horizon (" +
                          (ns ? us(st.position_scans.front().horizon) : std::string("?")) +
                          " us) T_p is not defined and the curve has a gap:";
    for (const TransientScan& s : st.position_scans) {
        caption += " " + std::to_string(unsettled(s)) + " of " + std::to_string(s.points.size()) + " positions for m = " +
                   std::to_string(s.elements) + ",";
    }
    caption.back() = '.';
    FigureSpec fig{"fig5", "Fig. 5: temporal characteristics against support position", caption, {{"fig5.csv", t.str()}}, p.str(),
                   1000, 900, 1.0, {}};
    ChartPanel a;
    a.title = "(a) duration of the transient (gaps: not settled within the horizon)";
    a.x_label = "support position x0/l [-]";
    a.y_label = "τ_p = ω_1 T_p [-]";
    a.x_marks = particular_marks();
    for (std::size_t k = 0; k < ns; ++k) {
        const std::string m = std::to_string(st.position_scans[k].elements);
        ChartSeries s = series("τ_p, m = " + m, "x0_over_l", mesh_prefix(st.position_scans[k].elements) + "tau_p", ChartSeries::Style::linespoints, color(static_cast<int>(k) + 1));
        s.dashed = k > 0;
        a.series.push_back(s);
    }
    fig.charts.push_back(a);
    if (ns) {
        const std::string m = std::to_string(st.position_scans.front().elements);
        const std::string pre = mesh_prefix(st.position_scans.front().elements);
        ChartPanel b;
        b.title = "(b) period τ, flight τ_1 and impact τ_2 of the first cycle, m = " + m;
        b.x_label = a.x_label;
        b.y_label = "τ, τ_1, τ_2 [-]";
        b.x_marks = particular_marks();
        b.series = {series("τ", "x0_over_l", pre + "tau", ChartSeries::Style::linespoints, color(3)),
                    series("τ_1", "x0_over_l", pre + "tau1", ChartSeries::Style::linespoints, color(4)),
                    series("τ_2", "x0_over_l", pre + "tau2", ChartSeries::Style::linespoints, color(5))};
        fig.charts.push_back(b);
    }
    return fig;
}

}  // namespace vi::figure_detail
