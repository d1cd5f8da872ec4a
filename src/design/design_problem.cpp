#include "design/design_problem.hpp"

#include <cmath>
#include <variant>

#include "io/range_spec.hpp"
#include "model/input_error.hpp"
#include "sweep/grid.hpp"

namespace vi {
namespace {

// Columns that hold text (why T_p ended, which solver ran, which support an impact hit), not numbers.
bool is_text_column(const std::string& name) { return sweep_column_is_text(name); }

}  // namespace

DesignVariable parse_design_variable(const std::string& text, const Case& c) {
    const auto fail = [&](const std::string& reason) { return InputError("--vary", text, reason); };
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) throw fail("expected PATH=LOW:HIGH, e.g. supports[0].position=0.3:1");
    DesignVariable v;
    v.setting = text;
    v.path = resolve_setting_path("--vary", text, c);
    if (is_integer_path(v.path)) {
        throw fail(v.path.text() + " takes whole numbers, which a continuous optimiser cannot vary; sweep it with --set");
    }
    const auto bounds = parse_bounds(text.substr(eq + 1), case_path_dimension(v.path));
    if (!bounds) throw fail("expected LOW:HIGH after '=', two finite numbers (SI, or with units as in case files)");
    if (!(bounds->first < bounds->second)) throw fail("LOW must be below HIGH");
    v.low = bounds->first;
    v.high = bounds->second;
    return v;
}

std::size_t quantity_column(const std::string& name, const std::vector<SweepColumn>& columns, const std::string& option) {
    for (std::size_t k = 0; k < columns.size(); ++k) {
        if (columns[k].name != name) continue;
        if (is_text_column(name)) throw InputError(option + " " + name + ": it is text, not a number");
        return k;
    }
    std::string names;
    for (const SweepColumn& col : columns) {
        if (is_text_column(col.name)) continue;
        if (!names.empty()) names += ", ";
        names += col.name;
    }
    throw InputError(option + " " + name + ": no such reported quantity (one of: " + names + ")");
}

DesignConstraint parse_design_constraint(const std::string& text, const std::vector<SweepColumn>& columns) {
    const auto fail = [&](const std::string& reason) { return InputError("--constraint " + text + ": " + reason); };
    std::size_t at = text.find("<=");
    DesignConstraint c;
    c.text = text;
    c.upper = at != std::string::npos;
    if (!c.upper) at = text.find(">=");
    if (at == std::string::npos) throw fail("expected NAME<=VALUE or NAME>=VALUE, e.g. impact1_peak_force_n<=1e-4");
    try {
        c.column = quantity_column(text.substr(0, at), columns, "--constraint");
    } catch (const InputError& e) {
        throw fail(e.what());
    }
    const std::optional<double> bound = finite_number(text.substr(at + 2));
    if (!bound) throw fail("VALUE must be a finite number in the quantity's SI unit");
    c.bound = *bound;
    return c;
}

bool DesignOutcome::feasible(const DesignProblem& p) const {
    if (!ok() || !objective) return false;
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        if (!constraints[k] || p.constraints[k].violation(*constraints[k]) > 0.0) return false;
    }
    return true;
}

DesignOutcome evaluate_design(const DesignProblem& p, const std::vector<double>& x) {
    std::vector<SweepAxis> axes;
    for (std::size_t i = 0; i < p.variables.size(); ++i) {
        axes.push_back(SweepAxis{p.variables[i].setting, p.variables[i].path, {x[i]}});
    }
    const SweepGrid grid(std::move(axes));
    const SweepPointResult r = run_sweep_point(p.base, grid, 0, p.settings);
    DesignOutcome out;
    out.status = r.status;
    out.constraints.assign(p.constraints.size(), std::nullopt);
    if (!r.ok()) return out;
    out.objective = numeric_cell(r.cells.at(p.objective));
    for (std::size_t k = 0; k < p.constraints.size(); ++k) out.constraints[k] = numeric_cell(r.cells.at(p.constraints[k].column));
    return out;
}

}  // namespace vi
