#include "uq/uq_summary.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "io/csv_reader.hpp"
#include "io/number_text.hpp"
#include "model/input_error.hpp"
#include "sweep/case_paths.hpp"
#include "uq/sobol_indices.hpp"
#include "uq/statistics.hpp"

namespace vi {
namespace {

using nlohmann::json;

json interval_json(const std::optional<Interval>& i) {
    return i ? json::array({i->low, i->high}) : json(nullptr);
}

// A number that may be NaN or infinite (JSON has neither): null then.
json number_json(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string percent_key(double p) { return round_trip_text(100.0 * p); }

json distribution_json(const UqInput& in) {
    const Distribution& d = in.distribution;
    json p;
    switch (d.kind) {
        case Distribution::Kind::normal: p = {{"mean", d.a}, {"sd", d.b}}; break;
        case Distribution::Kind::uniform: p = {{"low", d.a}, {"high", d.b}}; break;
        case Distribution::Kind::lognormal: p = {{"median", d.a}, {"sigma_log", d.b}}; break;
        case Distribution::Kind::truncnormal: p = {{"mean", d.a}, {"sd", d.b}, {"low", d.low}, {"high", d.high}}; break;
    }
    return {{"path", in.path.text()},         {"column", case_path_column(in.path)}, {"unit", case_path_unit(in.path)},
            {"setting", in.setting},          {"distribution", d.name()},           {"parameters", p},
            {"mean", d.mean()},               {"std", d.std_dev()}};
}

// The present values of a column over the base rows.
std::vector<double> base_values(const std::vector<double>& column, std::size_t rows) {
    std::vector<double> v;
    for (std::size_t r = 0; r < rows; ++r) {
        if (!std::isnan(column[r])) v.push_back(column[r]);
    }
    return v;
}

json moments_json(const std::vector<double>& v, const UqSettings& s, std::uint64_t column_seed) {
    json j;
    j["mean"] = number_json(sample_mean(v));
    j["mean_ci"] = interval_json(mean_interval(v, s.confidence));
    j["std"] = v.size() >= 2 ? number_json(sample_std(v)) : json(nullptr);
    const auto std_of = [&](const std::vector<std::size_t>& rows) {
        std::vector<double> x;
        x.reserve(rows.size());
        for (std::size_t r : rows) x.push_back(v[r]);
        return sample_std(x);
    };
    j["std_ci"] = v.size() >= 2 ? interval_json(bootstrap_interval(v.size(), s.resamples, column_seed, s.confidence, std_of))
                                : json(nullptr);
    std::vector<double> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    json q = json::object(), qci = json::object();
    for (double p : uq_quantile_levels()) {
        q[percent_key(p)] = number_json(sorted_quantile(sorted, p));
        qci[percent_key(p)] = interval_json(quantile_interval(sorted, p, s.confidence));
    }
    j["quantiles"] = q;
    j["quantile_ci"] = qci;
    return j;
}

// Runs whose analysis ran ("ok") among the base rows.
std::size_t ok_base_runs(const UqTable& t, std::size_t rows) {
    std::size_t n = 0;
    for (std::size_t r = 0; r < rows; ++r) n += t.status[r] == "ok" ? 1 : 0;
    return n;
}

json yield_json(const std::string& text, std::size_t passed, std::size_t evaluated, const UqSettings& s) {
    json j = {{"spec", text}, {"passed", passed}, {"evaluated", evaluated}};
    if (evaluated == 0) {
        j["yield"] = nullptr;
        j["ci"] = nullptr;
        return j;
    }
    const Interval ci = wilson_interval(passed, evaluated, s.confidence);
    j["yield"] = static_cast<double>(passed) / static_cast<double>(evaluated);
    j["ci"] = json::array({ci.low, ci.high});
    j["interval"] = "wilson";
    return j;
}

// Whether base run r meets spec k (a missing value does not).
bool meets(const UqTable& t, const YieldSpec& spec, std::size_t r) {
    const auto c = std::find(t.columns.begin(), t.columns.end(), spec.column) - t.columns.begin();
    const double v = t.values[static_cast<std::size_t>(c)][r];
    return !std::isnan(v) && spec.met(v);
}

json sobol_json(const SampleDesign& d, const std::vector<double>& column, const UqSettings& s, std::uint64_t seed,
                std::size_t& rows) {
    const std::size_t n = d.base;
    const auto block = [&](std::size_t b) {
        return std::vector<double>(column.begin() + static_cast<std::ptrdiff_t>(b * n),
                                   column.begin() + static_cast<std::ptrdiff_t>((b + 1) * n));
    };
    std::vector<std::vector<double>> ab;
    for (std::size_t i = 0; i < d.inputs.size(); ++i) ab.push_back(block(2 + i));
    const SobolEstimate e = sobol_indices(block(0), block(1), ab, s.resamples, seed, s.confidence);
    rows = e.rows;
    if (e.inputs.empty()) return nullptr;
    json j = json::object();
    for (std::size_t i = 0; i < d.inputs.size(); ++i) {
        const SobolIndex& x = e.inputs[i];
        j[d.inputs[i].path.text()] = {
            {"first", number_json(x.first)},
            {"total", number_json(x.total)},
            {"first_ci", x.has_ci ? json::array({x.first_ci.low, x.first_ci.high}) : json(nullptr)},
            {"total_ci", x.has_ci ? json::array({x.total_ci.low, x.total_ci.high}) : json(nullptr)}};
    }
    return j;
}

json column_json(const SampleDesign& d, const UqTable& t, std::size_t c, const UqSettings& s) {
    const std::size_t rows = d.base_rows();
    const std::vector<double> v = base_values(t.values[c], rows);
    json j = moments_json(v, s, derived_seed(s.seed, 1000 + 2 * c));
    j["n"] = v.size();
    j["missing"] = ok_base_runs(t, rows) - v.size();
    json yields = json::array();
    for (const YieldSpec& spec : s.specs) {
        if (spec.column != t.columns[c]) continue;
        std::size_t passed = 0;
        for (std::size_t r = 0; r < rows; ++r) passed += t.status[r] == "ok" && meets(t, spec, r) ? 1 : 0;
        yields.push_back(yield_json(spec.text, passed, ok_base_runs(t, rows), s));
    }
    j["yield"] = yields;
    if (d.sensitivity) {
        std::size_t used = 0;
        j["sobol"] = sobol_json(d, t.values[c], s, derived_seed(s.seed, 1001 + 2 * c), used);
        j["sobol_rows"] = used;
    }
    return j;
}

}  // namespace

const std::vector<double>& uq_quantile_levels() {
    static const std::vector<double> p = {0.01, 0.05, 0.5, 0.95, 0.99};
    return p;
}

UqTable uq_table_from_csv(const std::string& csv, std::size_t input_columns) {
    const std::vector<CsvRow> rows = split_csv(csv, "the samples' table");
    UqTable t;
    if (rows.empty()) return t;
    const std::vector<std::string>& header = rows.front().cells;
    const std::size_t width = header.size();
    for (std::size_t r = 1; r < rows.size(); ++r) {
        if (rows[r].cells.size() != width) throw InputError("the samples' table: row " + std::to_string(r) + " has another width");
        t.status.push_back(rows[r].cells.back());
    }
    for (std::size_t c = input_columns; c + 1 < width; ++c) {
        std::vector<double> col;
        bool numeric = true;
        for (std::size_t r = 1; r < rows.size() && numeric; ++r) {
            const std::optional<double> v = csv_cell_number(rows[r].cells[c]);
            numeric = v.has_value();
            col.push_back(v ? *v : std::nan(""));
        }
        if (!numeric) continue;
        // A failed run's cells are all missing; kept NaN.
        t.columns.push_back(header[c]);
        t.values.push_back(std::move(col));
    }
    return t;
}

json uq_summary_json(const SampleDesign& d, const UqTable& t, const UqSettings& s) {
    json j;
    j["analysis"] = s.analysis;
    j["method"] = sampling_method_name(s.method);
    j["seed"] = s.seed;
    j["samples"] = d.base;
    j["sensitivity"] = d.sensitivity;
    j["runs"] = d.runs();
    j["confidence"] = s.confidence;
    j["bootstrap_resamples"] = s.resamples;
    json inputs = json::array();
    for (const UqInput& in : d.inputs) inputs.push_back(distribution_json(in));
    j["inputs"] = inputs;
    json blocks = {{"A", {0, d.base}}};
    if (d.sensitivity) {
        blocks["B"] = {d.base, 2 * d.base};
        for (std::size_t i = 0; i < d.inputs.size(); ++i) {
            blocks["A_B[" + d.inputs[i].path.text() + "]"] = {(2 + i) * d.base, (3 + i) * d.base};
        }
    }
    j["blocks"] = blocks;
    json failures = json::array();
    for (std::size_t r = 0; r < t.status.size(); ++r) {
        if (t.status[r] != "ok") failures.push_back({{"index", r}, {"status", t.status[r]}});
    }
    j["failed"] = failures.size();
    j["failures"] = failures;
    json columns = json::object();
    for (std::size_t c = 0; c < t.columns.size(); ++c) columns[t.columns[c]] = column_json(d, t, c, s);
    j["columns"] = columns;
    if (s.specs.size() > 1) {
        std::size_t passed = 0;
        for (std::size_t r = 0; r < d.base_rows(); ++r) {
            bool all = t.status[r] == "ok";
            for (const YieldSpec& spec : s.specs) all = all && meets(t, spec, r);
            passed += all ? 1 : 0;
        }
        std::string text;
        for (const YieldSpec& spec : s.specs) text += (text.empty() ? "" : " and ") + spec.text;
        j["joint_yield"] = yield_json(text, passed, ok_base_runs(t, d.base_rows()), s);
    } else {
        j["joint_yield"] = nullptr;
    }
    return j;
}

}  // namespace vi
