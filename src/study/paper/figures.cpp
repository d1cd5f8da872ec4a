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

std::string scan_xrange(const PaperStudy& st) {
    return "set xrange [" + num(st.options.position_min - 0.02, 4) + ":1]\n";
}

std::string num(double v, int sig) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*g", sig, v);
    return buf;
}

std::string us(double seconds) { return num(seconds * 1e6, 4); }

}  // namespace figure_detail

std::vector<FigureSpec> paper_figures(const PaperStudy& study) {
    using namespace figure_detail;
    return {fig2(study), fig3(study), fig4(study), fig5(study), fig6(study),
            fig7(study), fig8(study), fig9(study), fig10(study), fig11(study)};
}

}  // namespace vi
