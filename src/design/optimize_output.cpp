#include "design/optimize_output.hpp"

#include <cstdint>
#include <vector>

#include "io/csv_writer.hpp"

namespace vi {
namespace {

CsvCell count(std::size_t n) { return csv_count(static_cast<std::int64_t>(n)); }

}  // namespace

std::string evaluations_csv(const DesignProblem& p, const OptimizeResult& r) {
    const std::string& q = p.columns[p.objective].name;
    CsvTable t;
    t.header = {"index", "stage"};
    for (const DesignVariable& v : p.variables) t.header.push_back(case_path_column(v.path));
    t.header.push_back(q);
    for (const DesignConstraint& c : p.constraints) t.header.push_back(p.columns[c.column].name);
    t.header.insert(t.header.end(), {"feasible", "best_" + q, "status"});
    for (const DesignEvaluation& e : r.evaluations) {
        std::vector<CsvCell> row{count(e.index), csv_text(e.stage)};
        for (double x : e.x) row.push_back(csv_number(x));
        row.push_back(csv_number(e.outcome.objective));
        for (const auto& c : e.outcome.constraints) row.push_back(csv_number(c));
        row.insert(row.end(), {csv_flag(e.feasible), csv_number(e.best), csv_text(e.outcome.status)});
        t.add_row(row);
    }
    return t.str();
}

nlohmann::json optimize_result_json(const DesignProblem& p, const OptimizeResult& r, const std::string& command) {
    nlohmann::json j;
    j["command"] = command;
    j["objective"] = {{"quantity", p.columns[p.objective].name}, {"sense", p.maximize ? "maximize" : "minimize"}};
    for (const DesignVariable& v : p.variables) j["variables"].push_back({{"path", v.path.text()}, {"low", v.low}, {"high", v.high}});
    j["constraints"] = nlohmann::json::array();
    for (const DesignConstraint& c : p.constraints) j["constraints"].push_back(c.text);
    int global = 0;
    for (const DesignEvaluation& e : r.evaluations) global += e.stage == "global" ? 1 : 0;
    j["evaluations"] = {{"global", global}, {"local", static_cast<int>(r.evaluations.size()) - global}};
    j["global_end"] = r.global_end;
    j["local_end"] = r.local_end;
    if (r.best) {
        const DesignEvaluation& b = r.evaluations[*r.best];
        nlohmann::json best;
        best["index"] = b.index;
        for (std::size_t i = 0; i < b.x.size(); ++i) best["x"][p.variables[i].path.text()] = b.x[i];
        best["objective"] = *b.outcome.objective;
        for (std::size_t k = 0; k < p.constraints.size(); ++k) best["constraints"][p.constraints[k].text] = *b.outcome.constraints[k];
        j["best"] = best;
    } else {
        j["best"] = nullptr;
    }
    return j;
}

nlohmann::json optimize_run_json(const OptimizeResult& r, double wall_s) {
    return {{"threads", r.threads},
            {"from_journal", r.reused},
            {"designs_computed", r.computed},
            {"rounds", r.batches},
            {"computed_ahead_unused", r.unused_guesses},
            {"look_ahead_stopped_after_rounds", r.look_ahead_stopped_after},
            {"look_ahead_s", r.look_ahead_s},
            {"wall_s", wall_s}};
}

}  // namespace vi
