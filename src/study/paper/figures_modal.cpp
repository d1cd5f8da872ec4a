// Figs. 2, 6, 7 and 8: the modes of the free cantilever and of the cantilever pinned at x0/l.

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "io/csv_writer.hpp"
#include "study/paper/figures.hpp"

namespace vi::figure_detail {

FigureSpec fig2(const PaperStudy& st) {
    const FreeModes& fm = st.free_modes;
    const int n = static_cast<int>(fm.shapes.size());
    CsvTable shapes;
    shapes.header = {"x_over_l"};
    for (int i = 1; i <= n; ++i) shapes.header.push_back("Y_" + std::to_string(i));
    for (int i = 1; i <= n; ++i) shapes.header.push_back("Phi_" + std::to_string(i));
    const std::size_t samples = n > 0 ? fm.shapes[0].x.size() : 0;
    for (std::size_t k = 0; k < samples; ++k) {
        std::vector<double> row{fm.shapes[0].x[k] / fm.length};
        for (int i = 0; i < n; ++i) row.push_back(fm.shapes[static_cast<std::size_t>(i)].v[k] * fm.amplitude_scale);
        for (int i = 0; i < n; ++i) row.push_back(fm.shapes[static_cast<std::size_t>(i)].theta[k] * fm.length * fm.amplitude_scale);
        shapes.add_row(row);
    }
    CsvTable points;
    points.header = {"mode", "kind", "j", "x_over_l", "amplitude"};
    const auto count = [](std::size_t j) { return csv_count(static_cast<std::int64_t>(j)); };
    for (int i = 0; i < n; ++i) {
        const ShapeFeatures& f = fm.result.bending[static_cast<std::size_t>(i)].features;
        const CsvCell mode = csv_count(i + 1);
        for (std::size_t j = 0; j < f.nodes.size(); ++j) {
            points.add_row({mode, csv_text("y"), count(j + 1), csv_number(f.nodes[j]), csv_number(0.0)});
        }
        for (std::size_t j = 0; j < f.rotation_nodes.size(); ++j) {
            points.add_row({mode, csv_text("phi"), count(j + 1), csv_number(f.rotation_nodes[j]), csv_number(0.0)});
        }
        for (std::size_t j = 0; j < f.peaks.size(); ++j) {
            points.add_row({mode, csv_text("Y"), count(j + 1), csv_number(f.peaks[j].x), csv_number(f.peaks[j].amplitude)});
        }
        for (std::size_t j = 0; j < f.rotation_peaks.size(); ++j) {
            points.add_row({mode, csv_text("Phi"), count(j + 1), csv_number(f.rotation_peaks[j].x), csv_number(f.rotation_peaks[j].amplitude)});
        }
    }
    std::ostringstream p;
    p << colors_command() << "set multiplot layout 2,1 title 'Natural modes of the free cantilever (m = "
      << fm.result.system.mesh.node_count() - 1 << "): (a) displacement Y, (b) rotation {/Symbol F}' font ',13'\n"
      << "set grid lc rgb '#dddddd'\nset xrange [0:1]\nset key outside right top\nset xzeroaxis lt -1\n"
      << "set lmargin 12\nset rmargin 22\n" << particular_points()
      // The legend sits outside the plot here: an opaque legend box would reach into the plot and
      // hide the curves' last few percent before x = l.
      << "set key noopaque\n"
      << "set ylabel 'Y = v (ρAl)^{1/2}  [-]'\nset xlabel 'x/l  [-]'\n"
      << "plot for [i=1:" << n << "] 'fig2.csv' using 1:(column(1+i)) with lines linewidth 2 linecolor rgb word(colors,i) "
         "title sprintf('mode %d', i), \\\n"
      << "  'fig2_points.csv' using (strcol(2) eq 'y' ? $4 : NaN):(0) with points pointtype 7 pointsize 0.9 "
         "linecolor rgb 'black' title 'nodal points y_{ij}'\n"
      << "set ylabel '{/Symbol F} = θ l (ρAl)^{1/2}  [-]'\n"
      << "plot for [i=1:" << n << "] 'fig2.csv' using 1:(column(1+" << n << "+i)) with lines linewidth 2 "
         "linecolor rgb word(colors,i) title sprintf('mode %d', i), \\\n"
      << "  'fig2_points.csv' using (strcol(2) eq 'phi' ? $4 : NaN):(0) with points pointtype 7 pointsize 0.9 "
         "linecolor rgb 'black' title 'nodal points {/Symbol f}_{ij}'\n"
      << "unset multiplot\n";
    const auto& b = fm.result.bending;
    std::string nodes;
    if (b.size() >= 3 && !b[1].features.nodes.empty() && b[2].features.nodes.size() >= 2) {
        nodes = " The nodal points the paper builds on: y_21 = " + significant(b[1].features.nodes[0], 4) + " (mode 2) and y_32 = " +
                significant(b[2].features.nodes[1], 4) + " (mode 3), the paper's 0.78 and 0.87.";
    }
    FigureSpec fig{"fig2", "Fig. 2: natural modes of the free cantilever",
                   "The first " + std::to_string(n) + " bending modes of the unsupported cantilever, mass-normalised and made "
                   "dimensionless, (a) displacement Y and (b) rotation Phi along the beam, with their nodal points (zeros, clamp "
                   "excluded). Dashed lines: the paper's particular points 0.67, 0.78, 0.87." + nodes,
                   {{"fig2.csv", shapes.str()}, {"fig2_points.csv", points.str()}}, p.str(), 1000, 900, 1.0, {}};
    for (const bool rotation : {false, true}) {
        ChartPanel c;
        c.title = rotation ? "(b) rotation Φ" : "(a) displacement Y";
        c.x_label = "x/l [-]";
        c.y_label = rotation ? "Φ = θ l (ρAl)^½ [-]" : "Y = v (ρAl)^½ [-]";
        c.x_marks = particular_marks();
        for (int i = 1; i <= n; ++i) {
            c.series.push_back(series("mode " + std::to_string(i), "x_over_l", (rotation ? "Phi_" : "Y_") + std::to_string(i),
                                      ChartSeries::Style::lines, color(i)));
        }
        ChartSeries pts = series(rotation ? "nodal points φ_ij" : "nodal points y_ij", "x_over_l", "amplitude",
                                 ChartSeries::Style::points, "#000000");
        pts.file = "fig2_points.csv";
        pts.where = {{"kind", rotation ? "phi" : "y"}};
        c.series.push_back(pts);
        fig.charts.push_back(c);
    }
    return fig;
}

namespace {

// Nodal points (Fig. 6) or peaks (Fig. 7) of the supported modes, one row per point.
CsvTable modal_points_csv(const PaperStudy& st, bool peaks) {
    CsvTable t;
    t.header = peaks ? std::vector<std::string>{"x0_over_l", "mode", "kind", "j", "x_over_l", "amplitude"}
                     : std::vector<std::string>{"x0_over_l", "mode", "kind", "j", "x_over_l", "at_support"};
    for (const ModalPoint& pt : st.modal) {
        if (!pt.error.empty()) continue;
        const CsvCell x0 = csv_number(pt.x0);
        const auto count = [](std::size_t j) { return csv_count(static_cast<std::int64_t>(j)); };
        for (std::size_t i = 0; i < pt.features.size(); ++i) {
            const ShapeFeatures& f = pt.features[i];
            const CsvCell mode = count(i + 1);
            if (peaks) {
                // A pin at the free end can leave a zero-amplitude "peak" there (docs/model.md, section 9).
                for (std::size_t j = 0; j < f.peaks.size(); ++j) {
                    if (f.peaks[j].amplitude > 1e-9) {
                        t.add_row({x0, mode, csv_text("Y"), count(j + 1), csv_number(f.peaks[j].x), csv_number(f.peaks[j].amplitude)});
                    }
                }
                for (std::size_t j = 0; j < f.rotation_peaks.size(); ++j) {
                    if (f.rotation_peaks[j].amplitude > 1e-9) {
                        t.add_row({x0, mode, csv_text("Phi"), count(j + 1), csv_number(f.rotation_peaks[j].x),
                                   csv_number(f.rotation_peaks[j].amplitude)});
                    }
                }
            } else {
                for (std::size_t j = 0; j < f.nodes.size(); ++j) {
                    const bool at = std::abs(f.nodes[j] - pt.x0) < 1e-9;
                    t.add_row({x0, mode, csv_text("y"), count(j + 1), csv_number(f.nodes[j]), csv_flag(at)});
                }
                for (std::size_t j = 0; j < f.rotation_nodes.size(); ++j) {
                    t.add_row({x0, mode, csv_text("phi"), count(j + 1), csv_number(f.rotation_nodes[j]), csv_flag(false)});
                }
            }
        }
    }
    return t;
}

// Fig. 7's peaks as lines: one row per support position, a column per (kind, mode, peak j) holding
// the j-th peak's amplitude (nan where that mode has no such peak there). Peak j of a mode moves
// continuously with the support, so a column is a curve; `count` gets the peaks per kind and mode.
CsvTable peak_lines_csv(const PaperStudy& st, std::map<std::pair<std::string, int>, std::size_t>& count) {
    const int n = st.options.modes;
    for (const ModalPoint& pt : st.modal) {
        if (!pt.error.empty()) continue;
        for (std::size_t i = 0; i < pt.features.size() && static_cast<int>(i) < n; ++i) {
            auto& y = count[{"Y", static_cast<int>(i) + 1}];
            auto& phi = count[{"Phi", static_cast<int>(i) + 1}];
            y = std::max(y, pt.features[i].peaks.size());
            phi = std::max(phi, pt.features[i].rotation_peaks.size());
        }
    }
    CsvTable t;
    t.header = {"x0_over_l"};
    for (const char* kind : {"Y", "Phi"}) {
        for (int i = 1; i <= n; ++i) {
            for (std::size_t j = 1; j <= count[{kind, i}]; ++j) t.header.push_back(std::string(kind) + "_" + std::to_string(i) + "_" + std::to_string(j));
        }
    }
    for (const ModalPoint& pt : st.modal) {
        if (!pt.error.empty()) continue;
        std::vector<double> row{pt.x0};
        for (const bool rotation : {false, true}) {
            for (int i = 1; i <= n; ++i) {
                const std::size_t m = count[{rotation ? "Phi" : "Y", i}];
                const std::size_t ii = static_cast<std::size_t>(i - 1);
                for (std::size_t j = 0; j < m; ++j) {
                    double a = std::nan("");
                    if (ii < pt.features.size()) {
                        const auto& peaks = rotation ? pt.features[ii].rotation_peaks : pt.features[ii].peaks;
                        // As in fig7.csv: a pin at the free end can leave a zero-amplitude "peak" there.
                        if (j < peaks.size() && peaks[j].amplitude > 1e-9) a = peaks[j].amplitude;
                    }
                    row.push_back(a);
                }
            }
        }
        t.add_row(row);
    }
    return t;
}

}  // namespace

FigureSpec fig6(const PaperStudy& st) {
    const int n = st.options.modes;
    std::ostringstream p;
    p << colors_command() << "set multiplot layout 1,2 title 'Nodal points of the supported cantilever (support as a pin at x_0/l)' font ',13'\n"
      << "set grid lc rgb '#dddddd'\nset xrange [0:1]\nset yrange [0:1]\nset size ratio -1\nset key bottom right font ',10'\n"
      << particular_points() << "set xlabel 'support position x_0/l  [-]'\n"
      << "set ylabel 'nodal point y_{ij}: x/l  [-]'\nset title '(a) displacement: zeros of v'\n"
      << "plot x with lines dashtype 3 linecolor rgb 'black' title 'support, y_{i0}', \\\n"
      << "  for [i=1:" << n << "] 'fig6.csv' using 1:(($2 == i && strcol(3) eq 'y' && $6 == 0) ? $5 : NaN) with points "
         "pointtype 7 pointsize 0.45 linecolor rgb word(colors,i) title sprintf('mode %d', i)\n"
      << "set ylabel 'nodal point {/Symbol f}_{ij}: x/l  [-]'\nset title '(b) rotation: zeros of θ'\n"
      << "plot x with lines dashtype 3 linecolor rgb 'black' title 'support', \\\n"
      << "  for [i=1:" << n << "] 'fig6.csv' using 1:(($2 == i && strcol(3) eq 'phi') ? $5 : NaN) with points "
         "pointtype 7 pointsize 0.45 linecolor rgb word(colors,i) title sprintf('mode %d', i)\n"
      << "unset multiplot\n";
    FigureSpec fig{"fig6", "Fig. 6: nodal points of the supported beam against the support position",
            "Zeros of the displacement v (a) and of the rotation theta (b) of the first " + std::to_string(n) +
                " modes of the cantilever with a pin at x0/l, against x0/l (" + std::to_string(st.modal.size()) +
                " positions). The dotted diagonal is the support itself, the extra nodal point y_i0 of every supported mode. "
                "Where the support sits on a nodal point of a free mode (0.78 for mode 2, 0.87 for mode 3), that mode is also a mode "
                "of the supported beam and its other nodal points stay where they were.",
            {{"fig6.csv", modal_points_csv(st, false).str()}}, p.str(), 1200, 640, 1.0, {}};
    for (const bool rotation : {false, true}) {
        ChartPanel c;
        c.title = rotation ? "(b) rotation: zeros of θ" : "(a) displacement: zeros of v";
        c.x_label = "support position x0/l [-]";
        c.y_label = rotation ? "nodal point φ_ij: x/l [-]" : "nodal point y_ij: x/l [-]";
        c.x_marks = particular_marks();
        // The support itself (the nodal point y_i0 of every mode): mode 1's zero at the support.
        ChartSeries support = series("support, y_i0", "x0_over_l", "x_over_l", ChartSeries::Style::lines, "#000000");
        support.where = {{"mode", "1"}, {"kind", "y"}, {"at_support", "1"}};
        support.dashed = true;
        c.series.push_back(support);
        for (int i = 1; i <= n; ++i) {
            ChartSeries m = series("mode " + std::to_string(i), "x0_over_l", "x_over_l", ChartSeries::Style::points, color(i));
            m.where = {{"mode", std::to_string(i)}, {"kind", rotation ? "phi" : "y"}};
            if (!rotation) m.where.emplace_back("at_support", "0");
            c.series.push_back(m);
        }
        fig.charts.push_back(c);
    }
    return fig;
}

FigureSpec fig7(const PaperStudy& st) {
    const int n = st.options.modes;
    std::map<std::pair<std::string, int>, std::size_t> count;
    const CsvTable lines = peak_lines_csv(st, count);
    // Lines per mode: each peak j of mode i is a curve over x0/l (column 1 + its place in fig7_lines.csv),
    // in the mode's colour, the legend naming the mode once.
    std::ostringstream p;
    p << colors_command() << "set multiplot layout 1,2 title 'Peak amplitudes of the supported modes against the support position' font ',13'\n"
      << "set grid lc rgb '#dddddd'\nset xrange [0:1]\nset key top left font ',10'\n" << particular_points()
      << "set xlabel 'support position x_0/l  [-]'\nset ylabel 'Y_{ij} = |v| (ρAl)^{1/2}  [-]'\nset title '(a) displacement peaks'\n";
    std::size_t col = 2;
    for (const bool rotation : {false, true}) {
        if (rotation) p << "set ylabel '{/Symbol F}_{ij} = |θ| l (ρAl)^{1/2}  [-]'\nset title '(b) rotation peaks'\n";
        std::string cmd = "plot ";
        for (int i = 1; i <= n; ++i) {
            const std::size_t m = count[{rotation ? "Phi" : "Y", i}];
            for (std::size_t j = 1; j <= m; ++j, ++col) {
                p << cmd << "'fig7_lines.csv' using 1:" << col << " with lines linewidth 1.8 "
                  << "linecolor rgb word(colors," << i << ") " << (j == 1 ? "title 'mode " + std::to_string(i) + "'" : std::string("notitle"));
                cmd = ", \\\n  ";
            }
        }
        if (cmd == "plot ") p << "plot NaN notitle";
        p << "\n";
    }
    p << "unset multiplot\n";
    FigureSpec fig{"fig7", "Fig. 7: peak amplitudes of the supported modes against the support position",
                   "Every local maximum of |v| (a) and of |theta| (b) of the first " + std::to_string(n) +
                       " supported modes (mass-normalised, dimensionless), against x0/l: the j-th peak of mode i (counted from "
                       "the clamp) is one line in the mode's colour. fig7_lines.csv holds these lines, fig7.csv each peak's "
                       "position x/l too.",
                   {{"fig7.csv", modal_points_csv(st, true).str()}, {"fig7_lines.csv", lines.str()}}, p.str(), 1200, 600, 1.0, {}};
    for (const bool rotation : {false, true}) {
        ChartPanel c;
        c.title = rotation ? "(b) rotation peaks" : "(a) displacement peaks";
        c.x_label = "support position x0/l [-]";
        c.y_label = rotation ? "Φ_ij = |θ| l (ρAl)^½ [-]" : "Y_ij = |v| (ρAl)^½ [-]";
        c.x_marks = particular_marks();
        const std::string kind = rotation ? "Phi" : "Y";
        for (int i = 1; i <= n; ++i) {
            for (std::size_t j = 1; j <= count[{kind, i}]; ++j) {
                ChartSeries s = series("mode " + std::to_string(i), "x0_over_l", kind + "_" + std::to_string(i) + "_" + std::to_string(j),
                                       ChartSeries::Style::lines, color(i));
                s.file = "fig7_lines.csv";
                s.group = "mode " + std::to_string(i);
                c.series.push_back(s);
            }
        }
        fig.charts.push_back(c);
    }
    return fig;
}

FigureSpec fig8(const PaperStudy& st) {
    const int n = st.options.modes;
    CsvTable t;
    t.header = {"x0_over_l"};
    for (int i = 1; i <= n; ++i) t.header.push_back("ratio_" + std::to_string(i));
    for (int i = 1; i <= n; ++i) t.header.push_back("f_supported_" + std::to_string(i) + "_hz");
    const double missing = std::nan("");
    for (const ModalPoint& pt : st.modal) {
        std::vector<double> row{pt.x0};
        for (int i = 0; i < n; ++i) row.push_back(static_cast<std::size_t>(i) < pt.ratio.size() ? pt.ratio[static_cast<std::size_t>(i)] : missing);
        for (int i = 0; i < n; ++i) {
            row.push_back(static_cast<std::size_t>(i) < pt.frequency_hz.size() ? pt.frequency_hz[static_cast<std::size_t>(i)] : missing);
        }
        t.add_row(row);
    }
    std::ostringstream p;
    p << colors_command() << "set grid lc rgb '#dddddd'\nset xrange [0:1]\nset key top left\n" << particular_points()
      << "set title 'Natural frequencies of the supported cantilever over those of the free one' font ',13'\n"
      << "set xlabel 'support position x_0/l  [-]'\nset ylabel 'ω_i / ω_{in}  [-]'\n"
      << "set label 1 sprintf('max ω_1/ω_{1n} = %.3f at x_0/l = %.4f', " << st.ratio_peak.ratio << ", " << st.ratio_peak.x0
      << ") at first " << st.ratio_peak.x0 << ", first " << st.ratio_peak.ratio << " right offset -1,0.8 font ',10'\n"
      << "plot for [i=1:" << n << "] 'fig8.csv' using 1:(column(1+i)) with lines linewidth 2 linecolor rgb word(colors,i) "
         "title sprintf('i = %d', i), \\\n"
      << "  '+' using (" << st.ratio_peak.x0 << "):(" << st.ratio_peak.ratio
      << ") every ::0::0 with points pointtype 6 pointsize 1.6 linecolor rgb 'black' notitle\n";
    FigureSpec fig{"fig8", "Fig. 8: supported over unsupported natural frequencies",
            "omega_i / omega_in for the first " + std::to_string(n) + " modes with a pin at x0/l (" + std::to_string(st.modal.size()) +
                " positions); the circle marks the largest omega_1 ratio, " + significant(st.ratio_peak.ratio, 4) + " at x0/l = " +
                significant(st.ratio_peak.x0, 5) + " (golden-section search), where the paper puts it at 0.78.",
            {{"fig8.csv", t.str()}}, p.str(), 1000, 620, 1.0, {}};
    ChartPanel c;
    c.x_label = "support position x0/l [-]";
    c.y_label = "ω_i / ω_in [-]";
    c.x_marks = particular_marks();
    for (int i = 1; i <= n; ++i) {
        c.series.push_back(series("i = " + std::to_string(i), "x0_over_l", "ratio_" + std::to_string(i), ChartSeries::Style::lines, color(i)));
    }
    fig.charts.push_back(c);
    return fig;
}

}  // namespace vi::figure_detail
