#pragma once
// What a spread study reports (uq.json): per result column the mean, standard deviation and
// quantiles with their confidence intervals, the yield against each spec, the Sobol indices of
// each input; the failed runs counted and listed (docs/uq.md).

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "uq/sample_design.hpp"
#include "uq/yield.hpp"

namespace vi {

// The runs' results as numbers: the numeric result columns of the analysis.
struct UqTable {
    std::vector<std::string> columns;         // numeric result columns, in the analysis's order
    std::vector<std::vector<double>> values;  // [column][run]; NaN where missing or the run failed
    std::vector<std::string> status;          // per run: "ok", "error: ...", "timeout: ..."
};

// The table of a sample design's CSV (the sweep table: the inputs' columns, the result columns,
// status), as sweep/table.hpp writes it: a result column is numeric when every cell of it reads as
// a number or the missing-value marker (text columns such as end_reason are left out). Throws
// InputError for CSV text it cannot read (a damaged journal's rows).
UqTable uq_table_from_csv(const std::string& csv, std::size_t input_columns);

struct UqSettings {
    std::string analysis;              // sweep analysis name
    SamplingMethod method = SamplingMethod::mc;
    std::uint64_t seed = 1;
    double confidence = 0.95;          // of every interval
    std::size_t resamples = 1000;      // bootstrap resamples (std's interval, Sobol indices')
    std::vector<YieldSpec> specs;
};

// The quantiles reported, as fractions (1, 5, 50, 95, 99 %).
const std::vector<double>& uq_quantile_levels();

// uq.json: {"case_name", "analysis", "method", "seed", "samples" (N), "sensitivity", "runs",
// "confidence", "inputs": [...], "blocks", "failed", "failures": [{"index", "status"}], "columns":
// {NAME: {"n", "missing", "mean", "mean_ci", "std", "std_ci", "quantiles": {"1": .., ...},
// "quantile_ci", "yield": [...], "sobol": {PATH: {"first", "total", "first_ci", "total_ci"}},
// "sobol_rows"}}, "joint_yield"}. Nothing in it depends on threads, ranks, time or a resume.
nlohmann::json uq_summary_json(const SampleDesign& design, const UqTable& table, const UqSettings& settings);

}  // namespace vi
