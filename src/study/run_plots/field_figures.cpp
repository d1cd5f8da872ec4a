// The animation of a simulate folder's field (field.csv, simulate --field): the deflected beam frame
// by frame as an animated GIF, at most kMaxAnimationFrames frames taken evenly from the field's.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "io/csv_writer.hpp"
#include "model/input_error.hpp"
#include "study/run_plots/plot_style.hpp"
#include "study/run_plots/run_figures.hpp"
#include "study/run_plots/run_table.hpp"

namespace vi {
namespace {

// The field's frames as read: rows [first, first + nodes) of each.
struct FieldLayout {
    std::size_t frames = 0;
    std::size_t nodes = 0;
};

FieldLayout field_layout(const RunTable& f, int frame) {
    const std::vector<double>& k = f.columns[static_cast<std::size_t>(frame)];
    FieldLayout l;
    while (l.nodes < f.rows && k[l.nodes] == 0.0) ++l.nodes;
    if (l.nodes < 2 || f.rows % l.nodes != 0) throw InputError(f.file + ": not one row per node and frame (frame 0 has " + std::to_string(l.nodes) + " rows)");
    l.frames = f.rows / l.nodes;
    for (std::size_t r = 0; r < f.rows; ++r) {
        if (k[r] != static_cast<double>(r / l.nodes)) {
            throw InputError(f.file + ":" + std::to_string(r + 2) + ": frame " + std::to_string(r / l.nodes) + " expected here");
        }
    }
    return l;
}

}  // namespace

std::vector<std::size_t> animation_frames(std::size_t frames) {
    std::vector<std::size_t> keep;
    const std::size_t n = std::min(frames, kMaxAnimationFrames);
    for (std::size_t i = 0; i < n; ++i) keep.push_back(n == 1 ? 0 : i * (frames - 1) / (n - 1));
    return keep;
}

std::vector<FigureSpec> field_figures(const std::string& dir, const std::string& case_name) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(dir + "/field.csv", ec)) return {};
    const RunTable f = read_run_table(dir + "/field.csv", true);
    const int ik = f.find("frame"), it = f.find("t_s"), ix = f.find("x_m"), iv = f.find("v_m");
    if (ik < 0 || it < 0 || ix < 0 || iv < 0) throw InputError(f.file + ":1: expected the columns frame, t_s, x_m, v_m");
    const FieldLayout l = field_layout(f, ik);
    const auto& x = f.columns[static_cast<std::size_t>(ix)];
    const auto& v = f.columns[static_cast<std::size_t>(iv)];
    const auto& t = f.columns[static_cast<std::size_t>(it)];
    const DisplayUnit xu = display_unit("m", largest_magnitude({&x}));
    const DisplayUnit vu = display_unit("m", largest_magnitude({&v}));
    const DisplayUnit tu = display_unit("s", largest_magnitude({&t}));
    FigureSpec fig = run_figure("field_animation", "The deflected beam over time" + (case_name.empty() ? "" : ": " + case_name),
                                "Transverse deflection along the beam (field.csv), one frame per field sample.");
    fig.width = 1200;
    fig.height = 600;
    fig.scale = 1.2;
    fig.animation_delay = 8;
    CsvTable data;
    data.header = {"x_m", "v_m"};
    const std::vector<std::size_t> keep = animation_frames(l.frames);
    for (std::size_t k : keep) {
        for (std::size_t i = 0; i < l.nodes; ++i) data.add_row({x[k * l.nodes + i], v[k * l.nodes + i]});
    }
    fig.data = {{"field_animation.csv", data.str()}};
    double lo = 0.0, hi = 0.0, xlo = 0.0, xhi = 0.0;
    finite_range({&v}, lo, hi);
    finite_range({&x}, xlo, xhi);
    std::ostringstream p;
    p << gp_frame(axis_label("x", xu), axis_label("deflection", vu)) << gp_range("x", xlo * xu.factor, xhi * xu.factor)
      << gp_range("y", lo * vu.factor, hi * vu.factor) << "set key top left\n";
    if (!std::isfinite(lo) || lo == hi) p << "set yrange [-1:1]\n";
    if (!case_name.empty()) p << "set title " << gp_quote(case_name) << " noenhanced\n";
    for (std::size_t j = 0; j < keep.size(); ++j) {
        const std::size_t a = j * l.nodes, b = a + l.nodes - 1;
        p << "plot 'field_animation.csv' every ::" << a + 1 << "::" << b + 1 << " using ($1*" << gp_number(xu.factor)
          << "):($2*" << gp_number(vu.factor) << ") with linespoints lw 2 pt 7 ps 0.6 lc rgb '#1f77b4' title "
          << gp_quote("t = " + gp_number(t[keep[j] * l.nodes] * tu.factor) + " " + tu.text) << " noenhanced\n";
    }
    fig.plot = p.str();
    return {fig};
}

}  // namespace vi
