// The figures of a simulate folder: every column of history.csv against time, one figure per unit
// (displacements with the supports' surfaces, velocities, forces, energies, any other), and the tip's
// phase portrait. Each figure's CSV holds its columns of history.csv as they are (SI, the same names);
// the gnuplot script scales them to the axes' units.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>

#include "model/input_error.hpp"
#include "io/csv_writer.hpp"
#include "study/run_plots/plot_style.hpp"
#include "study/run_plots/run_figures.hpp"
#include "study/run_plots/run_table.hpp"

namespace vi {
namespace {

// A support as summary.json describes it: where it sits along the beam and its surface's height.
struct SupportMark {
    double position = NAN;  // x/l
    double surface = NAN;   // [m]
};

std::vector<SupportMark> supports_of(const std::string& file) {
    const nlohmann::json j = read_run_json(file);
    std::vector<SupportMark> out;
    if (!j.is_object() || !j.contains("resolved") || !j["resolved"].is_object()) return out;
    const nlohmann::json& s = j["resolved"].value("supports", nlohmann::json::array());
    if (!s.is_array()) return out;
    for (const nlohmann::json& e : s) {
        SupportMark m;
        if (e.is_object() && e.contains("position") && e["position"].is_number()) m.position = e["position"].get<double>();
        if (e.is_object() && e.contains("surface_m") && e["surface_m"].is_number()) m.surface = e["surface_m"].get<double>();
        out.push_back(m);
    }
    return out;
}

// The legend text of a column: its quantity, and where a contact point sits ("contact 0 (x/l = 1)").
std::string series_title(const std::string& column, const std::vector<SupportMark>& supports) {
    std::string q = column_unit(column).quantity;
    if (q.rfind("contact", 0) == 0 && q.size() > 7 && std::isdigit(static_cast<unsigned char>(q[7]))) {
        std::size_t end = 7;
        while (end < q.size() && std::isdigit(static_cast<unsigned char>(q[end]))) ++end;
        const std::size_t k = std::stoul(q.substr(7, end - 7));
        std::string rest = q.substr(end);
        q = "contact " + q.substr(7, end - 7) + rest;
        if (k < supports.size() && std::isfinite(supports[k].position)) q += " (x/l = " + gp_number(supports[k].position) + ")";
    }
    return q;
}

struct UnitGroup {
    std::string unit;
    std::vector<int> columns;
};

// What each unit's figure is called and says.
struct GroupText {
    std::string name, title, axis, caption;
};

GroupText group_text(const std::string& unit) {
    if (unit == "m") {
        return {"transient_displacement", "Displacement of the tip and the contact points", "displacement",
                "Transverse displacement against time (history.csv); dotted lines: the supports' surfaces (summary.json)."};
    }
    if (unit == "m/s") {
        return {"transient_velocity", "Velocity of the tip and the contact points", "velocity",
                "Transverse velocity against time (history.csv)."};
    }
    if (unit == "N") return {"transient_force", "Contact forces", "force", "Force of each support on the beam against time (history.csv)."};
    if (unit == "J") {
        return {"transient_energy", "Energy ledger", "energy",
                "Energies stored, dissipated and put in since the start against time (history.csv)."};
    }
    if (unit.empty()) return {"transient_other", "Other quantities", "value", "The dimensionless columns of history.csv against time."};
    const std::string u = safe_name(unit);
    return {"transient_" + u, "Quantities in " + unit, "value", "The columns of history.csv in " + unit + " against time."};
}

FigureSpec group_figure(const RunTable& h, int it, const UnitGroup& g, const std::vector<SupportMark>& supports) {
    const GroupText text = group_text(g.unit);
    FigureSpec f = run_figure(text.name, text.title, text.caption);
    std::vector<const std::vector<double>*> cols;
    for (int k : g.columns) cols.push_back(&h.columns[static_cast<std::size_t>(k)]);
    std::vector<SupportMark> surfaces;
    if (g.unit == "m") {
        for (const SupportMark& s : supports) {
            if (std::isfinite(s.surface)) surfaces.push_back(s);
        }
    }
    double largest = largest_magnitude(cols);
    for (const SupportMark& s : surfaces) largest = std::max(largest, std::fabs(s.surface));
    const DisplayUnit tu = display_unit("s", largest_magnitude({&h.columns[static_cast<std::size_t>(it)]}));
    const DisplayUnit vu = display_unit(g.unit, largest);
    CsvTable data;
    data.header = {h.header[static_cast<std::size_t>(it)]};
    for (int k : g.columns) data.header.push_back(h.header[static_cast<std::size_t>(k)]);
    for (std::size_t r : rows_to_draw(cols, h.rows)) {
        std::vector<double> row{h.columns[static_cast<std::size_t>(it)][r]};
        for (const auto* c : cols) row.push_back((*c)[r]);
        data.add_row(row);
    }
    const std::string file = f.name + ".csv";
    f.data = {{file, data.str()}};
    double lo = 0.0, hi = 0.0;
    finite_range(cols, lo, hi);
    for (const SupportMark& s : surfaces) {
        lo = std::min(lo, s.surface);
        hi = std::max(hi, s.surface);
    }
    std::ostringstream p;
    p << gp_frame(axis_label("time", tu), axis_label(text.axis, vu)) << gp_range("y", lo * vu.factor, hi * vu.factor);
    p << "plot ";
    for (std::size_t i = 0; i < g.columns.size(); ++i) {
        p << (i ? ", " : "") << gp_quote(i ? "" : file) << " using ($1*" << gp_number(tu.factor) << "):($" << i + 2 << "*"
          << gp_number(vu.factor) << ") with lines lw 2 dt " << (i % 4 + 1) << " title "
          << gp_quote(series_title(h.header[static_cast<std::size_t>(g.columns[i])], supports)) << " noenhanced";
    }
    for (std::size_t k = 0; k < surfaces.size(); ++k) {
        p << ", " << gp_number(surfaces[k].surface * vu.factor) << " with lines dt 3 lw 1.5 lc rgb '#555555' title "
          << gp_quote("surface of support " + std::to_string(k)) << " noenhanced";
    }
    p << "\n";
    f.plot = p.str();
    return f;
}

FigureSpec phase_figure(const RunTable& h, int iy, int iv, const std::string& point) {
    FigureSpec f = run_figure("transient_phase", "Phase portrait of the " + point,
                              "Velocity against displacement of the " + point + " (history.csv); the dot marks the start.");
    const auto& y = h.columns[static_cast<std::size_t>(iy)];
    const auto& v = h.columns[static_cast<std::size_t>(iv)];
    const DisplayUnit yu = display_unit("m", largest_magnitude({&y}));
    const DisplayUnit vu = display_unit("m/s", largest_magnitude({&v}));
    CsvTable data;
    data.header = {h.header[static_cast<std::size_t>(iy)], h.header[static_cast<std::size_t>(iv)]};
    for (std::size_t r : rows_to_draw({&y, &v}, h.rows)) data.add_row({y[r], v[r]});
    f.data = {{"transient_phase.csv", data.str()}};
    double ylo = 0.0, yhi = 0.0, vlo = 0.0, vhi = 0.0;
    finite_range({&y}, ylo, yhi);
    finite_range({&v}, vlo, vhi);
    std::ostringstream p;
    p << gp_frame(axis_label(point + " displacement", yu), axis_label(point + " velocity", vu)) << gp_range("x", ylo * yu.factor, yhi * yu.factor)
      << gp_range("y", vlo * vu.factor, vhi * vu.factor) << "set key off\n";
    if (std::isfinite(y[0]) && std::isfinite(v[0])) {
        p << "set label 1 '' at first " << gp_number(y[0] * yu.factor) << ", first " << gp_number(v[0] * vu.factor)
          << " point pointtype 7 pointsize 2 lc rgb '#d62728' front\n";
    }
    p << "plot 'transient_phase.csv' using ($1*" << gp_number(yu.factor) << "):($2*" << gp_number(vu.factor)
      << ") with lines lw 1.5 lc rgb '#1f77b4'\n";
    f.plot = p.str();
    return f;
}

bool has_finite(const std::vector<double>& c) {
    return std::any_of(c.begin(), c.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

std::vector<FigureSpec> transient_figures(const std::string& dir, std::vector<std::string>& skipped) {
    const RunTable h = read_run_table(dir + "/history.csv", true);
    const int it = h.find("t_s");
    if (it < 0) throw InputError(h.file + ":1: no column t_s (time) in the header: not a simulate history");
    if (h.rows < 2) throw InputError(h.file + ": fewer than two rows of history: nothing to draw");
    std::vector<SupportMark> supports;
    try {
        supports = supports_of(dir + "/summary.json");
    } catch (const nlohmann::json::exception& e) {
        throw InputError(dir + "/summary.json: " + e.what());
    }
    std::vector<UnitGroup> groups;
    for (std::size_t k = 0; k < h.header.size(); ++k) {
        // A column without a finite value has nothing to draw (and gnuplot would warn about it).
        if (static_cast<int>(k) == it) continue;
        if (!has_finite(h.columns[k])) {
            skipped.push_back(h.header[k] + " (no finite value)");
            continue;
        }
        // A term that stays zero (no electrode's energy, no external work) would only add a flat
        // line and a legend entry saying nothing.
        if (std::all_of(h.columns[k].begin(), h.columns[k].end(), [](double v) { return v == 0.0; })) {
            skipped.push_back(h.header[k] + " (zero throughout)");
            continue;
        }
        const std::string unit = column_unit(h.header[k]).unit;
        auto g = std::find_if(groups.begin(), groups.end(), [&](const UnitGroup& x) { return x.unit == unit; });
        if (g == groups.end()) g = groups.insert(groups.end(), UnitGroup{unit, {}});
        g->columns.push_back(static_cast<int>(k));
    }
    std::vector<FigureSpec> figures;
    for (const UnitGroup& g : groups) figures.push_back(group_figure(h, it, g, supports));
    // The watched point: the free end (tip), or mid-span / a point of a beam held at both ends.
    int iy = -1, iv = -1;
    std::string point;
    for (const char* w : {"tip", "midspan", "point"}) {
        if (iy < 0 || iv < 0) {
            iy = h.find(std::string(w) + "_m");
            iv = h.find(std::string(w) + "_velocity_m_s");
            point = w;
        }
    }
    if (iy >= 0 && iv >= 0 && has_finite(h.columns[static_cast<std::size_t>(iy)]) && has_finite(h.columns[static_cast<std::size_t>(iv)])) {
        figures.push_back(phase_figure(h, iy, iv, point == "point" ? "watched point" : point));
    }
    return figures;
}

}  // namespace vi
