#pragma once
// A design problem: case values varied within bounds, one reported quantity to minimise or maximise,
// and inequality constraints on other reported quantities (docs/optimization.md).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/case.hpp"
#include "sweep/case_paths.hpp"
#include "sweep/columns.hpp"
#include "sweep/runner.hpp"

namespace vi {

// One varied value: "PATH=LOW:HIGH" (SI units, as --set), LOW < HIGH.
struct DesignVariable {
    std::string setting;
    CasePath path;
    double low = 0.0, high = 0.0;
};

// One constraint on a reported quantity: "NAME<=VALUE" or "NAME>=VALUE".
struct DesignConstraint {
    std::string text;
    std::size_t column = 0;  // in sweep_result_columns order
    bool upper = true;       // NAME <= bound (else NAME >= bound)
    double bound = 0.0;
    // How far a value breaks the constraint (> 0 broken, <= 0 held), in units of the quantity.
    [[nodiscard]] double violation(double value) const { return upper ? value - bound : bound - value; }
};

struct DesignProblem {
    Case base;
    std::vector<DesignVariable> variables;
    std::size_t objective = 0;  // column of the quantity (sweep_result_columns order)
    bool maximize = false;
    std::vector<DesignConstraint> constraints;
    std::vector<SweepColumn> columns;  // the reported quantities (a simulate sweep's columns)
    SweepSettings settings;            // how each design is computed (a simulate sweep point)
};

// Parses "PATH=LOW:HIGH" against the case. Throws InputError("--vary TEXT: reason").
DesignVariable parse_design_variable(const std::string& text, const Case& c);

// The column of a numeric reported quantity by name. Throws InputError(option + " NAME: reason")
// listing the names when there is none such.
std::size_t quantity_column(const std::string& name, const std::vector<SweepColumn>& columns, const std::string& option);

// Parses "NAME<=VALUE" or "NAME>=VALUE". Throws InputError("--constraint TEXT: reason").
DesignConstraint parse_design_constraint(const std::string& text, const std::vector<SweepColumn>& columns);

// One design's outcome: the point's status ("ok", or why it failed) and, when ok, the objective and
// each constraint's quantity (empty where the run reports none, e.g. no second impact).
struct DesignOutcome {
    std::string status;
    std::optional<double> objective;
    std::vector<std::optional<double>> constraints;
    [[nodiscard]] bool ok() const { return status == "ok"; }
    // ok, every quantity present, and every constraint held.
    [[nodiscard]] bool feasible(const DesignProblem& p) const;
};

// Computes the design x (one value per variable, SI) as a sweep point of the base case: checked,
// run within settings.point_timeout; never throws for a problem of the design itself. A stop
// request (StopRequested) passes through.
DesignOutcome evaluate_design(const DesignProblem& p, const std::vector<double>& x);

}  // namespace vi
