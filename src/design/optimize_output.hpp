#pragma once
// What an optimisation reports (docs/optimization.md): optimize.json's parts and evaluations.csv.

#include <nlohmann/json.hpp>
#include <string>

#include "design/design_problem.hpp"
#include "design/optimizer.hpp"

namespace vi {

// index, stage, each variable (its path and unit: supports[0].gap_m), the objective, each constraint's
// quantity, feasible, best_<objective> (the best feasible so far), status.
std::string evaluations_csv(const DesignProblem& p, const OptimizeResult& r);

// The problem, the stages' ends and the best design (null when none is feasible), with `command` as
// given; what does not depend on the threads.
nlohmann::json optimize_result_json(const DesignProblem& p, const OptimizeResult& r, const std::string& command);

// How the work went (threads, designs computed, rounds, wall time [s]): the only part of
// optimize.json that depends on the threads.
nlohmann::json optimize_run_json(const OptimizeResult& r, double wall_s);

}  // namespace vi
