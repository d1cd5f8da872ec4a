#include "plot/chart_json.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/csv_reader.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

// A CSV file of the figure: header and cells (io/csv_reader.hpp reads them as the writer wrote them).
struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

Table parse_csv(const std::string& text, const std::string& file) {
    Table t;
    for (CsvRow& row : split_csv(text, file)) {
        if (t.header.empty()) t.header = std::move(row.cells);
        else t.rows.push_back(std::move(row.cells));
    }
    return t;
}

std::size_t column(const Table& t, const std::string& name, const FigureSpec& f, const std::string& file) {
    for (std::size_t i = 0; i < t.header.size(); ++i) {
        if (t.header[i] == name) return i;
    }
    throw std::invalid_argument("figure " + f.name + ": a chart series names column '" + name + "', which " + file +
                                " does not have");
}

double number(const std::vector<std::string>& row, std::size_t i) {
    return i < row.size() ? csv_cell_number(row[i]).value_or(NAN) : NAN;
}

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '<': out += "\\u003c"; break;  // no "</script>" can end the element early
            case '>': out += "\\u003e"; break;
            case '&': out += "\\u0026"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
                    out += buf;
                } else {
                    out += c;
                }
        }
    }
    return out + "\"";
}

// 7 significant digits: more than a screen resolves, and the same text for the same CSV cell, so
// series read from one column line up on x.
std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    return significant(v, 7);
}

std::string json_numbers(const std::vector<double>& v) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (i) out += ',';
        out += json_number(v[i]);
    }
    return out + "]";
}

const char* style_name(ChartSeries::Style s) {
    switch (s) {
        case ChartSeries::Style::points: return "points";
        case ChartSeries::Style::linespoints: return "linespoints";
        case ChartSeries::Style::bars: return "bars";
        case ChartSeries::Style::lines: break;
    }
    return "lines";
}

struct Points {
    std::vector<double> x, y;
    std::vector<double> x_to, y_low, y_high;  // where the series names those columns
};

// The series' points in row order, in parts that a chart can draw: it joins a curve's points in the
// order of x, so a curve that turns back in x (a C-V curve through pull-in) or that a missing x
// interrupts is cut into runs along which x only grows or only falls; points alone are cut only where
// one x holds several (a cloud: the k-th point at an x goes to part k).
std::vector<Points> series_points(const FigureSpec& f, const std::map<std::string, Table>& tables, const ChartPanel& panel,
                                  const ChartSeries& s) {
    const std::string file = s.file.empty() ? (f.data.empty() ? std::string() : f.data.front().first) : s.file;
    const auto it = tables.find(file);
    if (it == tables.end()) {
        throw std::invalid_argument("figure " + f.name + ": a chart series reads data file '" + file + "', which the figure does not have");
    }
    const Table& t = it->second;
    const std::size_t cx = column(t, s.x, f, file);
    const std::size_t cy = column(t, s.y, f, file);
    std::vector<std::pair<std::size_t, std::string>> where;
    for (const auto& [name, value] : s.where) where.emplace_back(column(t, name, f, file), value);
    const auto optional_column = [&](const std::string& name) {
        return name.empty() ? std::optional<std::size_t>() : std::optional<std::size_t>(column(t, name, f, file));
    };
    const std::optional<std::size_t> cx_to = optional_column(s.x_to), c_low = optional_column(s.y_low),
                                     c_high = optional_column(s.y_high);
    // Bars and intervals stand alone at their x: never joined, so never cut.
    const bool cloud = s.style == ChartSeries::Style::points || s.style == ChartSeries::Style::bars;
    std::vector<Points> parts;
    std::map<double, std::size_t> seen;  // cloud: x -> points at it so far
    int direction = 0;                   // curve: +1 or -1 once the current run has two points
    bool cut = true;                     // curve: the next point starts a new run
    for (const auto& row : t.rows) {
        bool keep = true;
        for (const auto& [c, value] : where) keep = keep && c < row.size() && row[c] == value;
        if (!keep) continue;
        const double x = number(row, cx) * s.x_scale + s.x_offset;
        double y = number(row, cy) * s.y_scale;
        if (s.abs_y) y = std::abs(y);
        if (!std::isfinite(x) || (panel.log_x && x <= 0.0)) {
            cut = true;
            continue;
        }
        if (panel.log_y && !(y > 0.0)) y = NAN;
        std::size_t part = 0;
        if (cloud) {
            part = seen[x]++;
        } else {
            const int step = cut || parts.back().x.empty() ? 0 : (x > parts.back().x.back() ? 1 : x < parts.back().x.back() ? -1 : 2);
            if (cut || step == 2) {
                parts.emplace_back();
                direction = 0;
            } else if (direction != 0 && step != direction) {
                // The curve turns: the new run starts at the turning point, so that the curve stays whole.
                Points turn;
                turn.x.push_back(parts.back().x.back());
                turn.y.push_back(parts.back().y.back());
                parts.push_back(std::move(turn));
                direction = step;
            } else if (step != 0) {
                direction = step;
            }
            cut = false;
            part = parts.size() - 1;
        }
        if (part == parts.size()) parts.emplace_back();
        parts[part].x.push_back(x);
        parts[part].y.push_back(y);
        const auto scaled_y = [&](std::size_t c) {
            const double v = number(row, c) * s.y_scale;
            return panel.log_y && !(v > 0.0) ? NAN : v;
        };
        if (cx_to) parts[part].x_to.push_back(number(row, *cx_to) * s.x_scale + s.x_offset);
        if (c_low) parts[part].y_low.push_back(scaled_y(*c_low));
        if (c_high) parts[part].y_high.push_back(scaled_y(*c_high));
    }
    if (parts.empty()) parts.emplace_back();  // an empty series still has its legend entry
    return parts;
}

}  // namespace

std::string chart_json(const FigureSpec& f) {
    std::map<std::string, Table> tables;
    for (const auto& [name, text] : f.data) tables[name] = parse_csv(text, f.name + ": " + name);
    std::ostringstream s;
    s << "{\"panels\":[";
    int auto_group = 0;
    for (std::size_t p = 0; p < f.charts.size(); ++p) {
        const ChartPanel& panel = f.charts[p];
        s << (p ? "," : "") << "{\"title\":" << json_string(panel.title) << ",\"xLabel\":" << json_string(panel.x_label)
          << ",\"yLabel\":" << json_string(panel.y_label) << ",\"y2Label\":" << json_string(panel.y2_label)
          << ",\"logX\":" << (panel.log_x ? "true" : "false") << ",\"logY\":" << (panel.log_y ? "true" : "false")
          << ",\"xMin\":" << (panel.x_min ? json_number(*panel.x_min) : "null")
          << ",\"xMax\":" << (panel.x_max ? json_number(*panel.x_max) : "null") << ",\"marks\":" << json_numbers(panel.x_marks)
          << ",\"bands\":[";
        for (std::size_t b = 0; b < panel.x_bands.size(); ++b) {
            s << (b ? "," : "") << "[" << json_number(panel.x_bands[b].first) << "," << json_number(panel.x_bands[b].second) << "]";
        }
        s << "],\"xTicks\":[";
        for (std::size_t k = 0; k < panel.x_ticks.size(); ++k) {
            s << (k ? "," : "") << "[" << json_number(panel.x_ticks[k].first) << "," << json_string(panel.x_ticks[k].second) << "]";
        }
        s << "],\"series\":[";
        bool first = true;
        for (const ChartSeries& series : panel.series) {
            const std::vector<Points> parts = series_points(f, tables, panel, series);
            const std::string group = !series.group.empty() ? series.group
                                      : parts.size() > 1    ? " split " + std::to_string(auto_group++)
                                                            : std::string();
            for (const Points& part : parts) {
                s << (first ? "" : ",") << "{\"label\":" << json_string(series.label) << ",\"group\":" << json_string(group)
                  << ",\"style\":\"" << style_name(series.style) << "\",\"dash\":" << (series.dashed ? "true" : "false")
                  << ",\"right\":" << (series.right_axis ? "true" : "false") << ",\"color\":" << json_string(series.color)
                  << ",\"x\":" << json_numbers(part.x) << ",\"y\":" << json_numbers(part.y);
                if (series.style == ChartSeries::Style::bars) {
                    s << ",\"barWidth\":" << json_number(series.bar_width);
                    if (!series.x_to.empty()) s << ",\"xTo\":" << json_numbers(part.x_to);
                }
                if (!series.y_low.empty()) s << ",\"yLow\":" << json_numbers(part.y_low);
                if (!series.y_high.empty()) s << ",\"yHigh\":" << json_numbers(part.y_high);
                s << "}";
                first = false;
            }
        }
        s << "]}";
    }
    s << "]}";
    return s.str();
}

std::map<std::string, std::string> figure_charts(const std::vector<FigureSpec>& figures) {
    std::map<std::string, std::string> out;
    for (const FigureSpec& f : figures) {
        if (!f.charts.empty()) out[f.name] = chart_json(f);
    }
    return out;
}

}  // namespace vi
