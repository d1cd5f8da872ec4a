#include "study/paper/figures.hpp"

#include <cstdio>

namespace vi {
namespace figure_detail {

std::string colors_command() { return std::string("colors = \"") + kColors + "\"\n"; }

std::string particular_points() {
    // Tags from 91 on, so that a figure's own numbered arrows and labels never replace them.
    std::string s = "set tmargin 3.5\nset key opaque\n";  // opaque: the legend hides the dashed lines behind it
    int tag = 91;
    for (const char* p : {"0.67", "0.78", "0.87"}) {
        const std::string t = std::to_string(tag++);
        s += "set arrow " + t + " from first " + p + ", graph 0 to first " + p +
             ", graph 1 nohead dashtype 2 linewidth 1.2 linecolor rgb '#777777' back\n";
        s += "set label " + t + " '" + p + "' at first " + p + ", graph 1 center offset 0,0.7 font ',9' textcolor rgb '#555555'\n";
    }
    return s;
}

std::string color(int i) {
    std::vector<std::string> words;
    std::string w;
    for (const char* c = kColors;; ++c) {
        if (*c == ' ' || *c == '\0') {
            if (!w.empty()) words.push_back(w);
            w.clear();
            if (*c == '\0') break;
        } else {
            w += *c;
        }
    }
    return words[static_cast<std::size_t>(i - 1) % words.size()];
}

ChartSeries series(std::string label, std::string x, std::string y, ChartSeries::Style style, std::string colour) {
    ChartSeries s;
    s.label = std::move(label);
    s.x = std::move(x);
    s.y = std::move(y);
    s.style = style;
    s.color = std::move(colour);
    return s;
}

std::vector<double> particular_marks() { return {0.67, 0.78, 0.87}; }

std::string scan_xrange(const PaperStudy& st) {
    return "set xrange [" + significant(st.options.position_min - 0.02, 4) + ":1]\n";
}

std::string us(double seconds) { return significant(seconds * 1e6, 4); }

}  // namespace figure_detail

std::vector<FigureSpec> paper_figures(const PaperStudy& study) {
    using namespace figure_detail;
    return {fig2(study), fig3(study), fig4(study), fig5(study), fig6(study),
            fig7(study), fig8(study), fig9(study), fig10(study), fig11(study)};
}

}  // namespace vi
