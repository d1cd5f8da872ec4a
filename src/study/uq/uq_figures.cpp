#include "study/uq/uq_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "io/csv_writer.hpp"
#include "io/csv_names.hpp"
#include "uq/statistics.hpp"

namespace vi {
namespace {

// Bin edges over sorted values: Freedman-Diaconis width 2 IQR n^(-1/3), 5 to 100 bins.
std::vector<double> bin_edges(const std::vector<double>& sorted) {
    const double lo = sorted.front(), hi = sorted.back();
    if (!(hi > lo)) return {lo - 0.5 * std::abs(lo) - 0.5, hi + 0.5 * std::abs(hi) + 0.5};
    const double iqr = sorted_quantile(sorted, 0.75) - sorted_quantile(sorted, 0.25);
    const double width = 2.0 * iqr / std::cbrt(static_cast<double>(sorted.size()));
    const double bins = width > 0.0 ? std::ceil((hi - lo) / width) : std::sqrt(static_cast<double>(sorted.size()));
    const int n = static_cast<int>(std::clamp(bins, 5.0, 100.0));
    std::vector<double> edges;
    for (int k = 0; k <= n; ++k) edges.push_back(lo + (hi - lo) * k / n);
    return edges;
}

// The axis label of a column: its name and unit ("pullin_voltage_v" -> "pullin voltage [V]").
std::string axis_label(const std::string& column) {
    const CsvColumnUnit u = csv_column_unit(column);
    std::string name = u.stem;
    std::replace(name.begin(), name.end(), '_', ' ');
    return u.unit.empty() ? name : name + "  [" + u.unit + "]";
}

FigureSpec histogram(const std::string& column, const std::vector<double>& values, const std::vector<YieldSpec>& specs,
                     const std::string& case_name) {
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    const std::vector<double> edges = bin_edges(sorted);
    CsvTable t;
    t.header = {"from_" + column, "to_" + column, "samples"};
    std::size_t at = 0;
    for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
        std::size_t count = 0;
        const bool last = k + 2 == edges.size();
        while (at < sorted.size() && (sorted[at] < edges[k + 1] || last)) {
            ++count;
            ++at;
        }
        t.add_row({csv_number(edges[k]), csv_number(edges[k + 1]), csv_count(static_cast<std::int64_t>(count))});
    }
    FigureSpec f;
    f.name = "hist_" + column;
    f.title = "Spread of " + column;
    f.caption = "Case " + case_name + ": " + std::to_string(values.size()) + " samples of " + column +
                " (the base runs that gave a value); vertical lines: the specs on it. docs/uq.md";
    const std::string file = f.name + ".csv";
    f.data = {{file, t.str()}};
    std::string plot = "set grid\nset style fill solid 0.5 border\nset xlabel " + gp_quote(axis_label(column)) +
                       "\nset ylabel 'samples'\nset yrange [0:*]\nset key top right\n";
    for (const YieldSpec& s : specs) {
        if (s.column != column) continue;
        plot += "set arrow from " + gp_number(s.bound) + ", graph 0 to " + gp_number(s.bound) +
                ", graph 1 nohead lw 2 dt 2 lc rgb '#d62728'\n";
    }
    plot += "plot " + gp_quote(file) + " using (($1+$2)/2):3:($2-$1) with boxes lc rgb '#1f77b4' notitle\n";
    f.plot = plot;
    ChartPanel panel;
    panel.x_label = axis_label(column);
    panel.y_label = "samples";
    panel.x_min = edges.front();
    panel.x_max = edges.back();
    for (const YieldSpec& s : specs) {
        if (s.column == column) panel.x_marks.push_back(s.bound);
    }
    ChartSeries bars;
    bars.label = "samples per bin";
    bars.x = t.header[0];
    bars.x_to = t.header[1];
    bars.y = "samples";
    bars.style = ChartSeries::Style::bars;
    bars.color = "#1f77b4";
    panel.series = {bars};
    f.charts = {panel};
    return f;
}

FigureSpec sobol_bars(const std::string& column, const nlohmann::json& sobol, const std::string& case_name) {
    struct Row {
        std::string input;
        nlohmann::json x;
    };
    std::vector<Row> rows;
    for (const auto& [path, x] : sobol.items()) rows.push_back({path, x});
    const auto total = [](const Row& r) { return r.x["total"].is_number() ? r.x["total"].get<double>() : 0.0; };
    std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) { return total(a) > total(b); });
    CsvTable t;
    // input_index: the input's place on the chart's x axis (0, 1, ...), for the interactive chart.
    t.header = {"input", "sobol_first", "sobol_first_low", "sobol_first_high", "sobol_total", "sobol_total_low",
                "sobol_total_high", "input_index"};
    const auto num = [](const nlohmann::json& v) { return v.is_number() ? csv_number(v.get<double>()) : csv_missing(); };
    for (const Row& r : rows) {
        const nlohmann::json& fc = r.x["first_ci"];
        const nlohmann::json& tc = r.x["total_ci"];
        const nlohmann::json none;
        t.add_row({csv_text(r.input), num(r.x["first"]), num(fc.is_array() ? fc[0] : none), num(fc.is_array() ? fc[1] : none),
                   num(r.x["total"]), num(tc.is_array() ? tc[0] : none), num(tc.is_array() ? tc[1] : none),
                   csv_count(static_cast<std::int64_t>(&r - rows.data()))});
    }
    FigureSpec f;
    f.name = "sobol_" + column;
    f.title = "Which tolerance decides " + column;
    f.caption = "Case " + case_name + ": first-order (S_i) and total (S_Ti) Sobol indices of " + column +
                " per input, largest total first, with 95 % bootstrap intervals. docs/uq.md";
    const std::string file = f.name + ".csv";
    f.data = {{file, t.str()}};
    f.plot = "set grid ytics\nset style fill solid 0.6 border\nset ylabel 'Sobol index'\n"
             "set yrange [*<0:1<*]\nset xzeroaxis\nset xrange [-0.6:" + gp_number(static_cast<double>(rows.size()) - 0.4) +
             "]\nset key top right\nset xtics rotate by -20\n"
             // x:y:ylow:yhigh:width; `skip 1` passes the header, so that $0 counts the inputs from 0.
             "plot " + gp_quote(file) + " skip 1 using ($0-0.2):2:3:4:(0.35):xtic(1) with boxerrorbars lc rgb '#1f77b4' "
             "title 'first order S_i', '' skip 1 using ($0+0.2):5:6:7:(0.35) with boxerrorbars lc rgb '#ff7f0e' "
             "title 'total S_{Ti}'\n";
    ChartPanel panel;
    panel.x_label = "input";
    panel.y_label = "Sobol index";
    panel.x_min = -0.6;
    panel.x_max = static_cast<double>(rows.size()) - 0.4;
    for (std::size_t k = 0; k < rows.size(); ++k) panel.x_ticks.emplace_back(static_cast<double>(k), rows[k].input);
    const auto index_bars = [](const char* label, const std::string& stem, double offset, const char* color) {
        ChartSeries b;
        b.label = label;
        b.x = "input_index";
        b.x_offset = offset;
        b.y = stem;
        b.y_low = stem + "_low";
        b.y_high = stem + "_high";
        b.style = ChartSeries::Style::bars;
        b.bar_width = 0.35;
        b.color = color;
        return b;
    };
    panel.series = {index_bars("first order S_i", "sobol_first", -0.2, "#1f77b4"),
                    index_bars("total S_Ti", "sobol_total", 0.2, "#ff7f0e")};
    f.charts = {panel};
    return f;
}

}  // namespace

std::vector<FigureSpec> uq_figures(const nlohmann::json& summary, const UqTable& table, const SampleDesign& design,
                                   const std::vector<YieldSpec>& specs, const std::vector<std::string>& columns) {
    std::vector<FigureSpec> out;
    const std::string case_name = summary.value("case_name", "");
    for (const std::string& column : columns) {
        const auto c = std::find(table.columns.begin(), table.columns.end(), column);
        if (c == table.columns.end()) continue;
        const std::vector<double>& all = table.values[static_cast<std::size_t>(c - table.columns.begin())];
        std::vector<double> values;
        for (std::size_t r = 0; r < design.base_rows(); ++r) {
            if (!std::isnan(all[r])) values.push_back(all[r]);
        }
        if (values.empty()) continue;
        out.push_back(histogram(column, values, specs, case_name));
        const nlohmann::json& col = summary["columns"][column];
        if (col.contains("sobol") && col["sobol"].is_object()) out.push_back(sobol_bars(column, col["sobol"], case_name));
    }
    return out;
}

}  // namespace vi
