#include "study/uq/uq_report.hpp"

#include "model/number_format.hpp"
#include "plot/chart_json.hpp"

namespace vi {
namespace {

using json = nlohmann::json;

// j[key], or null where j has no such key (const operator[] would assert).
const json& at(const json& j, const char* key) {
    static const json none;
    return j.is_object() && j.contains(key) ? j[key] : none;
}

std::string num(const json& v) { return v.is_number() ? significant(v.get<double>(), 5) : std::string("-"); }

std::string interval(const json& ci) {
    return ci.is_array() && ci.size() == 2 ? num(ci[0]) + " .. " + num(ci[1]) : std::string("-");
}

std::string count(const json& v) { return v.is_number() ? std::to_string(v.get<long long>()) : std::string("-"); }

void study_blocks(ReportDocument& d, const json& j) {
    d.paragraph("Case `" + j.value("case", std::string()) + "`: " + count(at(j, "samples")) + " base samples (" +
                j.value("method", std::string()) + ", seed " + count(at(j, "seed")) + ") of the `" +
                j.value("analysis", std::string()) + "` analysis, " + count(at(j, "runs")) + " runs, " + count(at(j, "failed")) +
                " failed; intervals at " + num(at(j, "confidence")) + " confidence. Method, estimators and files: docs/uq.md.");
    std::vector<std::vector<std::string>> rows;
    for (const json& in : at(j, "inputs")) {
        std::string params;
        for (const auto& [k, v] : at(in, "parameters").items()) params += (params.empty() ? "" : ", ") + k + " " + num(v);
        rows.push_back({"`" + in.value("path", std::string()) + "`", in.value("distribution", std::string()), params,
                        num(at(in, "mean")), num(at(in, "std")), in.value("unit", std::string())});
    }
    d.heading(2, "Inputs", "inputs");
    d.table({"path", "distribution", "parameters", "mean", "std", "unit"}, rows);
    if (at(j, "joint_yield").is_object()) {
        const json& y = at(j, "joint_yield");
        d.paragraph("Joint yield (every spec at once): " + num(at(y, "yield")) + " (" + count(at(y, "passed")) + " of " +
                    count(at(y, "evaluated")) + "; Wilson interval " + interval(at(y, "ci")) + ").");
    }
}

void column_blocks(ReportDocument& d, const std::string& name, const json& c, const std::vector<FigureSpec>& figures,
                   const std::map<std::string, std::string>& png) {
    d.heading(2, name, "column-" + name);
    const json& q = at(c, "quantiles");
    const json& qci = at(c, "quantile_ci");
    std::vector<std::vector<std::string>> rows = {
        {"mean", num(at(c, "mean")), interval(at(c, "mean_ci"))},
        {"standard deviation", num(at(c, "std")), interval(at(c, "std_ci"))},
    };
    for (const char* p : {"1", "5", "50", "95", "99"}) {
        rows.push_back({std::string(p) + " % quantile", num(at(q, p)), interval(at(qci, p))});
    }
    d.table({"statistic", "value", "interval"}, rows);
    d.paragraph(count(at(c, "n")) + " values, " + count(at(c, "missing")) + " base runs without one.");
    if (at(c, "yield").is_array() && !at(c, "yield").empty()) {
        std::vector<std::vector<std::string>> ys;
        for (const json& y : at(c, "yield")) {
            ys.push_back({"`" + y.value("spec", std::string()) + "`", num(at(y, "yield")),
                          count(at(y, "passed")) + " of " + count(at(y, "evaluated")), interval(at(y, "ci"))});
        }
        d.table({"spec", "yield", "passed", "Wilson interval"}, ys);
    }
    if (at(c, "sobol").is_object()) {
        std::vector<std::vector<std::string>> ss;
        for (const auto& [path, x] : at(c, "sobol").items()) {
            ss.push_back({"`" + path + "`", num(at(x, "first")), interval(at(x, "first_ci")), num(at(x, "total")), interval(at(x, "total_ci"))});
        }
        d.table({"input", "first order S_i", "interval", "total S_Ti", "interval"}, ss);
    }
    for (const FigureSpec& f : figures) {
        if (f.name != "hist_" + name && f.name != "sobol_" + name) continue;
        if (png.count(f.name) == 0) {
            d.paragraph("Figure `" + f.name + "` was not drawn (see the command's message).");
            continue;
        }
        d.figure(f.name, f.title, f.caption, {f.name + ".csv", f.name + ".gp", f.name + ".svg"});
    }
}

}  // namespace

ReportDocument uq_report(const json& summary, const std::vector<std::string>& columns,
                         const std::vector<FigureSpec>& figures, const std::map<std::string, std::string>& png) {
    ReportDocument d;
    d.title = "Spread: " + summary.value("case_name", std::string());
    d.heading(1, d.title);
    study_blocks(d, summary);
    for (const std::string& name : columns) {
        const json& cols = at(summary, "columns");
        if (!cols.is_object() || !cols.contains(name)) continue;
        column_blocks(d, name, cols[name], figures, png);
    }
    d.heading(2, "Files", "files");
    d.list({"`uq.json`: every column's statistics, yields and Sobol indices; `samples.csv`: every run's inputs and results",
            "`hist_*` and `sobol_*`: each figure's PNG, SVG, data (CSV) and gnuplot script (`gnuplot hist_x.gp` redraws it)"});
    return d;
}

std::string uq_html(const json& summary, const std::vector<std::string>& columns, const std::vector<FigureSpec>& figures,
                    const std::map<std::string, std::string>& png) {
    std::vector<FigureSpec> drawn;
    for (const FigureSpec& f : figures) {
        if (png.count(f.name) > 0) drawn.push_back(f);
    }
    return render_html(uq_report(summary, columns, figures, png), png, figure_charts(drawn));
}

}  // namespace vi
