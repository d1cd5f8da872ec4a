// Figs. 9, 10 and 11: the rebound against prestress, and the impacts themselves.

#include <cmath>
#include <sstream>

#include "study/paper/curve_features.hpp"
#include "study/paper/claims.hpp"
#include "io/csv_writer.hpp"
#include "study/paper/figures.hpp"

namespace vi::figure_detail {

FigureSpec fig9(const PaperStudy& st) {
    const TransientScan& s = st.prestress;
    CsvTable t;
    t.header = {"delta_over_l", "z_max", "z_equilibrium", "z_top", "tau_p", "status"};
    for (const TransientPoint& p : s.points) {
        std::optional<double> top;
        if (p.z_max && p.z_equilibrium) top = *p.z_max + *p.z_equilibrium;
        t.add_row({csv_number(p.x), csv_number(p.z_max), csv_number(p.z_equilibrium), csv_number(top), csv_number(p.tau_p), status(p)});
    }
    const auto minima = local_minima(scan_x(s), scan_z_max(s));
    std::ostringstream p;
    p << "set grid lc rgb '#dddddd'\nset key top right\n"
      << "set title 'Rebound against the prestress of a support at the free end' font ',13'\n"
      << "set xlabel 'prestress Δ/l  [-]'\nset ylabel 'z_{max} = y_{max}/l above the equilibrium  [10^{-3}]'\n"
      << "set arrow 1 from first 0.01, graph 0 to first 0.01, graph 1 nohead dashtype 2 linewidth 1.2 linecolor rgb '#777777'\n"
      << "set label 1 'paper: point B, Δ/l = 0.01' at first 0.01, graph 0.06 left offset 0.5,0 font ',10' textcolor rgb '#555555'\n";
    std::string extra;
    if (!minima.empty()) {
        p << "set label 2 sprintf('first local minimum: Δ/l = %.4f', " << minima.front().x << ") at first " << minima.front().x
          << ", first " << minima.front().y * 1e3 << " left offset 1,-1.2 font ',10'\n";
        extra = ", \\\n  '+' using (" + gp_number(minima.front().x) + "):(" + gp_number(minima.front().y * 1e3) +
                ") every ::0::0 with points pointtype 6 pointsize 2 linecolor rgb 'black' title 'first local minimum (parabola)'";
    }
    p << "plot 'fig9.csv' using 1:($2*1e3) with linespoints pointtype 7 pointsize 0.7 linewidth 2 linecolor rgb '#1f77b4' "
         "title sprintf('z_{max}, lift y_0 = %.2f μm', "
      << st.options.cases.prestress.initial.displacement * 1e6 << ")" << extra << "\n";
    std::string caption = "Largest rebound of the free end above its (prestressed) equilibrium against the prestress Delta/l of a "
                          "support under the free end (" + std::to_string(s.points.size()) + " values, 0 to " +
                          significant(s.points.empty() ? 0.0 : s.points.back().x, 3) + "); the beam is lifted " +
                          significant(st.options.cases.prestress.initial.displacement * 1e6, 3) +
                          " um above that equilibrium and released. The CSV also gives the equilibrium z_equilibrium (about Delta/l: "
                          "the paper's diagonal) and the highest point z_top above the unloaded axis." + failures(s);
    FigureSpec fig{"fig9", "Fig. 9: rebound against prestress", caption, {{"fig9.csv", t.str()}}, p.str(), 1000, 620, 1.0, {}};
    ChartPanel c;
    c.x_label = "prestress Δ/l [-]";
    c.y_label = "z_max = y_max/l above the equilibrium [10⁻³]";
    c.x_marks = {0.01};  // the paper's point B
    ChartSeries z = series("z_max", "delta_over_l", "z_max", ChartSeries::Style::linespoints, "#1f77b4");
    z.y_scale = 1e3;
    c.series.push_back(z);
    fig.charts.push_back(c);
    return fig;
}

FigureSpec fig10(const PaperStudy& st) {
    CsvTable t;
    t.header = {"x0_over_l"};
    for (int i = 1; i <= 3; ++i) t.header.push_back("v_in_" + std::to_string(i) + "_m_s");
    for (int i = 1; i <= 3; ++i) t.header.push_back("peak_force_" + std::to_string(i) + "_un");
    t.header.push_back("status");
    if (!st.position_scans.empty()) {
        for (const TransientPoint& p : st.position_scans.front().points) {
            std::vector<CsvCell> row{csv_number(p.x)};
            for (std::size_t i = 0; i < 3; ++i) row.push_back(i < p.impacts.size() ? csv_number(p.impacts[i].v_in) : csv_missing());
            for (std::size_t i = 0; i < 3; ++i) row.push_back(i < p.impacts.size() ? csv_number(p.impacts[i].peak_force * 1e6) : csv_missing());
            row.push_back(status(p));
            t.add_row(row);
        }
    }
    std::ostringstream p;
    p << colors_command() << "set grid lc rgb '#dddddd'\nset key top left font ',10'\n" << particular_points() << scan_xrange(st)
      << "set title 'Pre-impact velocity and peak contact force of the first three impacts, m = "
      << (st.position_scans.empty() ? 0 : st.position_scans.front().elements) << "' font ',13'\n"
      << "set xlabel 'support position x_0/l  [-]'\nset ylabel 'pre-impact velocity |v_{in}| of the contact point  [m/s]'\n"
      << "set y2label 'peak contact force P  [μN]'\nset ytics nomirror\nset y2tics\nset yrange [0:*]\nset y2range [0:*]\n"
      << "plot for [i=1:3] 'fig10.csv' using 1:(abs(column(1+i))) with linespoints pointtype 7 pointsize 0.5 linewidth 2 "
         "linecolor rgb word(colors,i) title sprintf('|v_{in}|, impact %s', i==1 ? 'I' : i==2 ? 'II' : 'III'), \\\n"
      << "  for [i=1:3] 'fig10.csv' using 1:(column(4+i)) axes x1y2 with lines dashtype 2 linewidth 2 linecolor rgb word(colors,i) "
         "title sprintf('P, impact %s', i==1 ? 'I' : i==2 ? 'II' : 'III')\n";
    std::string caption = "Velocity of the contact point just before impacts I, II, III (solid) and their largest contact force "
                          "(dashed, right axis) as the support moves; episodes closer than a quarter of the first period form one "
                          "impact, whose force is the largest of its episodes.";
    if (!st.position_scans.empty()) caption += failures(st.position_scans.front());
    FigureSpec fig{"fig10", "Fig. 10: impact velocity and contact force against support position", caption, {{"fig10.csv", t.str()}},
                   p.str(), 1000, 620, 1.0, {}};
    ChartPanel c;
    c.x_label = "support position x0/l [-]";
    c.y_label = "pre-impact velocity |v_in| [m/s]";
    c.y2_label = "peak contact force P [μN]";
    c.x_marks = particular_marks();
    const char* roman[] = {"I", "II", "III"};
    for (int i = 1; i <= 3; ++i) {
        ChartSeries v = series(std::string("|v_in|, impact ") + roman[i - 1], "x0_over_l", "v_in_" + std::to_string(i) + "_m_s",
                               ChartSeries::Style::linespoints, color(i));
        v.abs_y = true;
        c.series.push_back(v);
    }
    for (int i = 1; i <= 3; ++i) {
        ChartSeries f = series(std::string("P, impact ") + roman[i - 1], "x0_over_l", "peak_force_" + std::to_string(i) + "_un",
                               ChartSeries::Style::lines, color(i));
        f.dashed = true;
        f.right_axis = true;
        c.series.push_back(f);
    }
    fig.charts.push_back(c);
    return fig;
}

FigureSpec fig11(const PaperStudy& st) {
    CsvTable t;
    t.header = {"x0_over_l", "t_us", "tau", "force_un"};
    for (const ImpactForce& f : st.forces) {
        for (std::size_t i = 0; i < f.t.size(); ++i) t.add_row({f.x0, f.t[i] * 1e6, f.t[i] * f.omega1, f.force[i] * 1e6});
    }
    std::ostringstream p;
    p << colors_command() << "set grid lc rgb '#dddddd'\nset key top right\n"
      << "set title 'Contact force during the first impact' font ',13'\n"
      << "set xlabel 'time since the onset of the impact  t  [μs]'\nset ylabel 'contact force P  [μN]'\n"
      << "set x2label 'τ = ω_1 t  [-]'\nset xtics nomirror\nset x2tics\nset link x2 via x*" << (st.forces.empty() ? 1.0 : st.forces.front().omega1 * 1e-6)
      << " inverse x/" << (st.forces.empty() ? 1.0 : st.forces.front().omega1 * 1e-6) << "\nset x2tics 0.1\n";
    std::string cmd = "plot ";
    std::string caption = "Contact force against time through the first impact (its episodes grouped) with the support at";
    for (std::size_t k = 0; k < st.forces.size(); ++k) {
        const ImpactForce& f = st.forces[k];
        const double T2 = f.impact.t_off - f.impact.t_on;
        p << cmd << "'fig11.csv' using 2:((abs($1 - " << f.x0 << ") < 1e-9) ? $4 : NaN) with lines linewidth 2 linecolor rgb word(colors,"
          << k + 1 << ") title sprintf('x_0/l = %g: T_2 = %.3f μs, τ_2 = %.3f, " << f.impact.episodes << " episode(s)', " << f.x0
          << ", " << T2 * 1e6 << ", " << T2 * f.omega1 << ")";
        cmd = ", \\\n  ";
        caption += (k ? (k + 1 == st.forces.size() ? " and " : ", ") : " ") + significant(f.x0, 3) + " (T2 = " + us(T2) + " us)";
    }
    p << "\n";
    caption += "; sampled every 2.5 ns. Top axis: the same time made dimensionless with the first free frequency.";
    FigureSpec fig{"fig11", "Fig. 11: contact force during an impact", caption, {{"fig11.csv", t.str()}}, p.str(), 1000, 620, 1.0, {}};
    ChartPanel c;
    c.x_label = "time since the onset of the impact t [μs]";
    c.y_label = "contact force P [μN]";
    for (std::size_t k = 0; k < st.forces.size(); ++k) {
        const ImpactForce& f = st.forces[k];
        ChartSeries s = series("x0/l = " + significant(f.x0, 4), "t_us", "force_un", ChartSeries::Style::lines, color(static_cast<int>(k) + 1));
        s.where = {{"x0_over_l", csv_number(f.x0).text()}};
        c.series.push_back(s);
    }
    fig.charts.push_back(c);
    return fig;
}

}  // namespace vi::figure_detail
