// The figures of a sweep folder: each numeric reported quantity of sweep.csv against the one varying
// axis of sweep.json, or as a heat map over two. Points without a value (a failed point, a quantity
// the run does not define) are left out: a gap in the line, a grey cell in the map. Each figure's CSV
// holds sweep.csv's values as they are (SI, the same column names); the gnuplot script scales them.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "io/csv_writer.hpp"
#include "study/run_plots/plot_style.hpp"
#include "study/run_plots/run_figures.hpp"
#include "study/run_plots/run_table.hpp"

namespace vi {
namespace {

// A varying axis of the grid: the case path, its unit, its values in grid order, its column in sweep.csv.
struct PlotAxis {
    std::string path, unit;
    std::string name;            // its column's name in sweep.csv ("supports[0].gap_m")
    std::vector<double> values;  // sorted, distinct
    bool log = false;            // a log:start:stop:count range: drawn on a log scale
    int column = -1;
    DisplayUnit shown;
};

std::vector<PlotAxis> varying_axes(const nlohmann::json& j, const RunTable& t, const std::string& json_file) {
    std::vector<PlotAxis> out;
    if (!j.is_object() || !j.contains("axes") || !j["axes"].is_array()) throw InputError(json_file + ": no \"axes\" list: not a sweep's description");
    for (const nlohmann::json& a : j["axes"]) {
        PlotAxis x;
        x.path = a.at("path").get<std::string>();
        x.unit = a.value("unit", std::string());
        for (const nlohmann::json& v : a.at("values")) {
            if (v.is_number()) x.values.push_back(v.get<double>());
        }
        std::sort(x.values.begin(), x.values.end());
        x.values.erase(std::unique(x.values.begin(), x.values.end()), x.values.end());
        if (x.values.size() < 2) continue;  // a value set once: not an axis of the figures
        x.log = a.value("setting", std::string()).find("=log:") != std::string::npos && x.values.front() > 0.0;
        // The column's name (sweep.json "column"); a folder written before the name carried the unit
        // has the path alone.
        x.name = a.value("column", x.path);
        x.column = t.find(x.name);
        if (x.column < 0) throw InputError(t.file + ":1: no column " + x.name + " for the axis " + x.path + " of " + json_file);
        x.shown = display_unit(x.unit, std::max(std::fabs(x.values.front()), std::fabs(x.values.back())));
        out.push_back(std::move(x));
    }
    return out;
}

// The unit of each result column as sweep.json gives it.
std::map<std::string, std::string> column_units(const nlohmann::json& j) {
    std::map<std::string, std::string> out;
    if (!j.contains("columns") || !j["columns"].is_array()) return out;
    for (const nlohmann::json& c : j["columns"]) {
        if (c.is_object() && c.contains("name") && c["name"].is_string()) out[c["name"].get<std::string>()] = c.value("unit", std::string());
    }
    return out;
}

// A quantity of sweep.csv with its name as a label and its unit.
struct Quantity {
    int column = -1;
    std::string label, unit;
};

// The edges of the cells around sorted axis values: midway between neighbours (geometrically on a
// log axis), the outer ones as far out as the inner ones.
std::vector<double> cell_edges(const PlotAxis& a) {
    const auto& v = a.values;
    const auto mid = [&](double p, double q) { return a.log ? std::sqrt(p * q) : 0.5 * (p + q); };
    std::vector<double> e(v.size() + 1);
    for (std::size_t i = 1; i < v.size(); ++i) e[i] = mid(v[i - 1], v[i]);
    e.front() = a.log ? v[0] * v[0] / e[1] : 2.0 * v[0] - e[1];
    e.back() = a.log ? v.back() * v.back() / e[v.size() - 1] : 2.0 * v.back() - e[v.size() - 1];
    return e;
}

// The grid value nearest x (sweep.csv and sweep.json write the same values to the last digit), by
// bisection of the sorted values: a heat map may hold 10^8 points.
std::size_t index_of(const PlotAxis& a, double x) {
    const auto it = std::lower_bound(a.values.begin(), a.values.end(), x);
    if (it == a.values.begin()) return 0;
    const std::size_t i = static_cast<std::size_t>(it - a.values.begin());
    if (i == a.values.size()) return i - 1;
    return std::fabs(a.values[i] - x) < std::fabs(a.values[i - 1] - x) ? i : i - 1;
}

// A heat map keeps at most this many grid values per axis: a 2400 px wide figure shows no more
// cells, and gnuplot draws every cell as a shape of its own (the SVG grows with them).
constexpr std::size_t kMaxCellsPerAxis = 500;

// Every how many grid values one is drawn on an axis of a heat map (1: all of them).
std::size_t cell_stride(const PlotAxis& a) { return (a.values.size() + kMaxCellsPerAxis - 1) / kMaxCellsPerAxis; }

// The axis with every stride-th value only (the first among them), for a heat map's cells.
PlotAxis every_nth(const PlotAxis& a, std::size_t stride) {
    PlotAxis out = a;
    out.values.clear();
    for (std::size_t i = 0; i < a.values.size(); i += stride) out.values.push_back(a.values[i]);
    return out;
}

std::string axis_text(const PlotAxis& a) {
    return axis_label(a.path, a.shown);
}

// Columns drawn in one figure: those of one physical unit (every time, every force, ...), or for
// plain numbers and counts those whose names differ only in digits (tau, tau1, tau2).
struct Family {
    std::string key, title;
    std::vector<Quantity> members;
};

bool physical_unit(const std::string& unit) { return !unit.empty() && unit != "-" && unit != "count" && unit != "index"; }

// What the columns of a unit are, for a figure's title and file name ("Times", "sweep_times").
std::string unit_family_title(const std::string& unit) {
    static const std::map<std::string, std::string> words = {
        {"s", "Times"},          {"m", "Displacements"}, {"m/s", "Velocities"}, {"N", "Forces"},
        {"J", "Energies"},       {"Hz", "Frequencies"},  {"rad/s", "Circular frequencies"},
        {"N s", "Impulses"},     {"V", "Voltages"},      {"Pa", "Pressures"}, {"ohm", "Resistances"}};
    const auto w = words.find(unit);
    return w != words.end() ? w->second : "Quantities in " + unit;
}

std::string family_key(const Quantity& q, const std::string& name) {
    if (physical_unit(q.unit)) return "unit " + q.unit;
    std::string k;
    for (char c : name) {
        if (!std::isdigit(static_cast<unsigned char>(c))) k += c;
    }
    return "name " + k;
}

FigureSpec line_figure(const RunTable& t, const PlotAxis& a, const Family& fam) {
    const auto& x = t.columns[static_cast<std::size_t>(a.column)];
    std::vector<const std::vector<double>*> ys_all;
    for (const Quantity& q : fam.members) ys_all.push_back(&t.columns[static_cast<std::size_t>(q.column)]);
    const std::string unit = fam.members.front().unit;
    const DisplayUnit yu = display_unit(unit, largest_magnitude(ys_all));
    std::string names;
    for (const Quantity& q : fam.members) names += (names.empty() ? "" : ", ") + t.header[static_cast<std::size_t>(q.column)];
    std::string stem = t.header[static_cast<std::size_t>(fam.members.front().column)];
    if (fam.members.size() > 1) {
        stem = physical_unit(unit) ? unit_family_title(unit) : fam.key.substr(fam.key.find(' ') + 1);
        for (char& c : stem) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    FigureSpec f = run_figure("sweep_" + safe_name(stem), fam.title + " against " + a.path,
                              names + " of sweep.csv against " + a.path +
                                  "; a gap: a point without a value (failed, or the quantity undefined there).");
    std::vector<std::size_t> order(t.rows);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return x[i] < x[j]; });
    // A long sweep is drawn from the points that shape its curves, as a long history is (in each
    // slice the first, the last, the lowest and the highest): every peak survives.
    std::vector<std::vector<double>> sorted(ys_all.size());
    std::vector<double> xs;
    for (std::size_t r : order) {
        xs.push_back(x[r]);
        for (std::size_t m = 0; m < ys_all.size(); ++m) sorted[m].push_back((*ys_all[m])[r]);
    }
    std::vector<const std::vector<double>*> sorted_ptr;
    for (const auto& c : sorted) sorted_ptr.push_back(&c);
    const std::vector<std::size_t> drawn = rows_to_draw(sorted_ptr, xs.size());
    if (drawn.size() < xs.size()) {
        f.caption += " Drawn from " + std::to_string(drawn.size()) + " of the " + std::to_string(xs.size()) +
                     " points (in each slice of the axis the first, the last, the lowest and the highest).";
    }
    CsvTable data;
    data.header = {t.header[static_cast<std::size_t>(a.column)]};
    for (const Quantity& q : fam.members) data.header.push_back(t.header[static_cast<std::size_t>(q.column)]);
    for (std::size_t r : drawn) {
        std::vector<double> row{xs[r]};
        for (const auto& c : sorted) row.push_back(c[r]);
        data.add_row(row);
    }
    const std::string file = f.name + ".csv";
    f.data = {{file, data.str()}};
    double lo = 0.0, hi = 0.0;
    finite_range(ys_all, lo, hi);
    std::ostringstream p;
    p << gp_frame(axis_text(a), axis_label(fam.members.size() == 1 ? fam.members.front().label : fam.title, yu))
      << (fam.members.size() == 1 ? "set key off\n" : "")
      << "set xrange [" << gp_number(a.values.front() * a.shown.factor) << ":" << gp_number(a.values.back() * a.shown.factor) << "]\n"
      << gp_range("y", lo * yu.factor, hi * yu.factor) << (a.log ? "set logscale x\n" : "") << "plot ";
    for (std::size_t m = 0; m < fam.members.size(); ++m) {
        p << (m ? ", " : "") << gp_quote(m ? "" : file) << " using ($1*" << gp_number(a.shown.factor) << "):($" << m + 2 << "*"
          << gp_number(yu.factor) << ") with linespoints lw 2 pt " << (m % 6 + 5) << " ps 1.4 dt " << (m % 4 + 1)
          << " title " << gp_quote(fam.members[m].label) << " noenhanced";
    }
    p << "\n";
    f.plot = p.str();
    return f;
}

FigureSpec heat_figure(const RunTable& t, const PlotAxis& ax, const PlotAxis& ay, const Quantity& q) {
    const auto& z = t.columns[static_cast<std::size_t>(q.column)];
    const DisplayUnit zu = display_unit(q.unit, largest_magnitude({&z}));
    FigureSpec f = run_figure("sweep_" + safe_name(t.header[static_cast<std::size_t>(q.column)]), q.label + " over " + ax.path + " and " + ay.path,
                              t.header[static_cast<std::size_t>(q.column)] + " of sweep.csv, one cell per grid point; grey: a point "
                                  "without a value (failed, or the quantity undefined there).");
    // A grid finer than the figure can show is drawn on a sub-grid of its own points (every n-th
    // value of an axis, each cell widened to its neighbours'): values are shown, never averaged.
    const std::size_t sx = cell_stride(ax), sy = cell_stride(ay);
    const PlotAxis dx = every_nth(ax, sx), dy = every_nth(ay, sy);
    if (sx > 1 || sy > 1) {
        f.caption += " Drawn on a sub-grid of " + std::to_string(dx.values.size()) + " x " + std::to_string(dy.values.size()) +
                     " of the " + std::to_string(ax.values.size()) + " x " + std::to_string(ay.values.size()) +
                     " grid values (every " + std::to_string(sx) + "th of " + ax.path + ", every " + std::to_string(sy) +
                     "th of " + ay.path + ").";
    }
    const std::vector<double> ex = cell_edges(dx), ey = cell_edges(dy);
    // Each point's cell spans low_<x> to high_<x> and low_<y> to high_<y>.
    CsvTable data;
    data.header = {ax.name, ay.name, "low_" + ax.name, "high_" + ax.name, "low_" + ay.name, "high_" + ay.name,
                   t.header[static_cast<std::size_t>(q.column)]};
    const auto& xs = t.columns[static_cast<std::size_t>(ax.column)];
    const auto& ys = t.columns[static_cast<std::size_t>(ay.column)];
    for (std::size_t r = 0; r < t.rows; ++r) {
        if (!std::isfinite(z[r]) || !std::isfinite(xs[r]) || !std::isfinite(ys[r])) continue;
        const std::size_t i = index_of(ax, xs[r]), k = index_of(ay, ys[r]);
        if (i % sx != 0 || k % sy != 0) continue;
        data.add_row({xs[r], ys[r], ex[i / sx], ex[i / sx + 1], ey[k / sy], ey[k / sy + 1], z[r]});
    }
    const std::string file = f.name + ".csv";
    f.data = {{file, data.str()}};
    double lo = 0.0, hi = 0.0;
    finite_range({&z}, lo, hi);
    const std::string fx = gp_number(ax.shown.factor), fy = gp_number(ay.shown.factor);
    std::ostringstream p;
    p << gp_frame(axis_text(ax), axis_text(ay)) << "set key off\nunset grid\n"
      << "set cblabel " << gp_quote(axis_label(q.label, zu)) << " noenhanced\n"
      << "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21908d', 3 '#5dc863', 4 '#fde725')\n"
      << "set object 1 rectangle from graph 0, graph 0 to graph 1, graph 1 behind fillcolor rgb '#bbbbbb' fillstyle solid 1.0 noborder\n"
      << "set xrange [" << gp_number(ex.front() * ax.shown.factor) << ":" << gp_number(ex.back() * ax.shown.factor) << "]\n"
      << "set yrange [" << gp_number(ey.front() * ay.shown.factor) << ":" << gp_number(ey.back() * ay.shown.factor) << "]\n"
      << (hi > lo ? std::string() : gp_range("cb", lo * zu.factor, hi * zu.factor)) << (ax.log ? "set logscale x\n" : "")
      << (ay.log ? "set logscale y\n" : "")
      << "plot " << gp_quote(file) << " using ($1*" << fx << "):($2*" << fy << "):($3*" << fx << "):($4*" << fx << "):($5*" << fy
      << "):($6*" << fy << "):($7*" << gp_number(zu.factor) << ") with boxxyerror fillstyle solid 1.0 noborder linecolor palette\n";
    f.plot = p.str();
    return f;
}

}  // namespace

std::vector<FigureSpec> sweep_figures(const std::string& dir, std::vector<std::string>& skipped) {
    const std::string json_file = dir + "/sweep.json";
    const RunTable t = read_run_table(dir + "/sweep.csv", false);
    const nlohmann::json j = read_run_json(json_file);
    if (j.is_null()) throw InputError(json_file + ": missing; it names the sweep's axes and units (sweep --out writes it)");
    std::vector<PlotAxis> axes;
    std::map<std::string, std::string> units;
    try {
        axes = varying_axes(j, t, json_file);
        units = column_units(j);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(one_line(json_file + ": " + e.what()));
    }
    if (axes.empty()) throw InputError(json_file + ": no axis takes two values or more: nothing varies to draw against");
    if (axes.size() > 2) {
        throw InputError(json_file + ": " + std::to_string(axes.size()) +
                         " axes vary; plot draws a sweep over one axis (curves) or two (heat maps)");
    }
    std::vector<FigureSpec> figures;
    std::vector<Family> families;
    for (std::size_t k = 0; k < t.header.size(); ++k) {
        const std::string& name = t.header[k];
        const bool axis = std::any_of(axes.begin(), axes.end(), [&](const PlotAxis& a) { return a.column == static_cast<int>(k); });
        const auto& c = t.columns[k];
        if (axis) continue;
        if (t.text[k] || !std::any_of(c.begin(), c.end(), [](double v) { return std::isfinite(v); })) {
            skipped.push_back(name + (t.text[k] ? " (text)" : " (no finite value)"));
            continue;
        }
        // The same value at every point (the support every first impact hits) says nothing against the axes.
        double lo = 0.0, hi = 0.0;
        finite_range({&c}, lo, hi);
        if (lo == hi) {
            skipped.push_back(name + " (constant: " + gp_number(lo) + ")");
            continue;
        }
        Quantity q{static_cast<int>(k), name, ""};
        const ColumnUnit cu = column_unit(name);
        const auto u = units.find(name);
        q.unit = u != units.end() ? u->second : cu.unit;
        if (cu.unit == q.unit) q.label = cu.quantity;
        if (axes.size() == 2) {
            figures.push_back(heat_figure(t, axes[0], axes[1], q));
            continue;
        }
        const std::string key = family_key(q, name);
        auto fam = std::find_if(families.begin(), families.end(), [&](const Family& x) { return x.key == key; });
        if (fam == families.end()) {
            const std::string title = physical_unit(q.unit) ? unit_family_title(q.unit) : q.label;
            fam = families.insert(families.end(), Family{key, title, {}});
        }
        fam->members.push_back(q);
    }
    for (Family& fam : families) {
        if (fam.members.size() == 1) fam.title = fam.members.front().label;
        figures.push_back(line_figure(t, axes[0], fam));
    }
    if (figures.empty()) throw InputError(t.file + ": no column holds a number to draw (every point failed?)");
    return figures;
}

}  // namespace vi
