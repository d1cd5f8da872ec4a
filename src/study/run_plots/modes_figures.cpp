// The figures of a modes folder: the bending mode shapes of the free beam and of the beam on its
// supports, each scaled to a peak of 1, with the nodal points that modes.json lists.

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "model/input_error.hpp"
#include "io/csv_writer.hpp"
#include "study/run_plots/plot_style.hpp"
#include "study/run_plots/run_figures.hpp"
#include "study/run_plots/run_table.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

// What modes.json says of bending mode k of one set: its frequency [Hz] and nodal points [x/l].
struct ModeFacts {
    double frequency = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> nodes;
};

std::vector<ModeFacts> mode_facts(const nlohmann::json& j, const std::string& set) {
    std::vector<ModeFacts> out;
    if (!j.is_object() || !j.contains(set) || !j[set].is_object()) return out;
    const nlohmann::json& bending = j[set].value("bending", nlohmann::json::array());
    if (!bending.is_array()) return out;
    for (const nlohmann::json& m : bending) {
        ModeFacts f;
        if (m.is_object() && m.contains("frequency_hz") && m["frequency_hz"].is_number()) f.frequency = m["frequency_hz"].get<double>();
        if (m.is_object() && m.contains("nodes") && m["nodes"].is_array()) {
            for (const nlohmann::json& x : m["nodes"]) {
                if (x.is_number()) f.nodes.push_back(x.get<double>());
            }
        }
        out.push_back(std::move(f));
    }
    return out;
}

std::string frequency_text(double hz) {
    const DisplayUnit u = display_unit("Hz", std::fabs(hz));
    return significant(hz * u.factor, 4) + " " + u.text;
}

FigureSpec shapes_figure(const std::string& dir, const std::string& set, const std::vector<ModeFacts>& facts) {
    const RunTable t = read_run_table(dir + "/shapes_" + set + ".csv", true);
    const int ix = t.find("x_over_l");
    if (ix < 0) throw InputError(t.file + ":1: no column x_over_l in the header: not a modes shape file");
    std::vector<int> shapes;
    for (int k = 1; k <= 1000; ++k) {
        // v_<k> alone: a folder written before the column names carried the unit.
        int c = t.find("v_" + std::to_string(k) + "_per_sqrt_kg");
        if (c < 0) c = t.find("v_" + std::to_string(k));
        if (c < 0) break;
        shapes.push_back(c);
    }
    if (shapes.empty()) throw InputError(t.file + ":1: no column v_1_per_sqrt_kg in the header: no mode shape to draw");
    const std::string name = "modes_" + set;
    const bool free = set == "unsupported";
    FigureSpec f = run_figure(name, free ? "Mode shapes without supports" : "Mode shapes on the supports",
                              "Bending mode shapes (" + t.file.substr(dir.size() + 1) + "), each scaled to a peak of 1, against the "
                              "position along the beam; dots: nodal points (modes.json).");
    CsvTable data;
    data.header = {"x_over_l"};
    std::vector<double> peak;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        data.header.push_back("v_" + std::to_string(i + 1) + "_over_peak");
        peak.push_back(largest_magnitude({&t.columns[static_cast<std::size_t>(shapes[i])]}));
    }
    for (std::size_t r = 0; r < t.rows; ++r) {
        std::vector<double> row{t.columns[static_cast<std::size_t>(ix)][r]};
        for (std::size_t i = 0; i < shapes.size(); ++i) {
            const double v = t.columns[static_cast<std::size_t>(shapes[i])][r];
            row.push_back(peak[i] > 0.0 ? v / peak[i] : v);
        }
        data.add_row(row);
    }
    // The nodal points: one row per node, its value 0 in its mode's column and missing in the others.
    CsvTable nodes;
    nodes.header = {"x_over_l"};
    for (std::size_t i = 0; i < shapes.size(); ++i) nodes.header.push_back("mode_" + std::to_string(i + 1));
    for (std::size_t i = 0; i < shapes.size() && i < facts.size(); ++i) {
        for (double x : facts[i].nodes) {
            std::vector<double> row(shapes.size() + 1, std::numeric_limits<double>::quiet_NaN());
            row[0] = x;
            row[i + 1] = 0.0;
            nodes.add_row(row);
        }
    }
    const std::string file = name + ".csv", node_file = name + "_nodes.csv";
    f.data = {{file, data.str()}};
    if (nodes.rows() > 0) f.data.emplace_back(node_file, nodes.str());
    std::ostringstream p;
    p << gp_frame("position along the beam  x/l", "deflection / peak") << "set xrange [0:1]\nset yrange [-1.15:1.15]\n"
      << "set key outside right top\nset xzeroaxis lt -1 lw 1\n";
    p << "plot ";
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        std::string title = "mode " + std::to_string(i + 1);
        if (i < facts.size() && std::isfinite(facts[i].frequency)) title += ": " + frequency_text(facts[i].frequency);
        p << (i ? ", " : "") << gp_quote(file) << " using 1:" << i + 2 << " with lines lw 2 lt " << i + 1 << " title " << gp_quote(title);
    }
    if (nodes.rows() > 0) {
        for (std::size_t i = 0; i < shapes.size() && i < facts.size(); ++i) {
            if (facts[i].nodes.empty()) continue;  // gnuplot warns about a column without a point
            p << ", " << gp_quote(node_file) << " using 1:" << i + 2 << " with points pt 7 ps 3.5 lt " << i + 1 << " notitle";
        }
    }
    p << "\n";
    f.plot = p.str();
    return f;
}

}  // namespace

std::vector<FigureSpec> modes_figures(const std::string& dir) {
    nlohmann::json j;
    try {
        j = read_run_json(dir + "/modes.json");
    } catch (const nlohmann::json::exception& e) {
        throw InputError(dir + "/modes.json: " + e.what());
    }
    std::vector<FigureSpec> figures;
    for (const std::string set : {"unsupported", "supported"}) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(dir + "/shapes_" + set + ".csv", ec)) continue;
        figures.push_back(shapes_figure(dir, set, mode_facts(j, set)));
    }
    return figures;
}

}  // namespace vi
