#include "study/analyses/design_setup.hpp"

#include "model/input_error.hpp"
#include "study/analyses/sweep_analyses.hpp"

namespace vi {

DesignProblem design_problem(const Case& base, const DesignRequest& q) {
    if (q.minimize.empty() == q.maximize.empty()) throw InputError("optimize: give one of --minimize or --maximize");
    if (q.modes < 1 || q.modes > 100) throw InputError("--modes: must be 1 to 100 (got " + std::to_string(q.modes) + ")");
    if (!(q.point_timeout >= 0.0)) throw InputError("--point-timeout: must be 0 (none) or positive seconds");
    if (q.vary.empty()) throw InputError("--vary: at least one PATH=LOW:HIGH is needed");
    DesignProblem p;
    p.base = base;
    p.settings.analysis = parse_sweep_analysis(q.analysis);
    p.settings.modes = q.modes;
    p.settings.point_timeout = q.point_timeout;
    p.settings = with_study_analyses(p.settings);
    check_sweep_analysis(p.base, p.settings);
    p.columns = sweep_result_columns(p.settings.analysis, p.settings.modes);
    for (const std::string& v : q.vary) {
        DesignVariable variable = parse_design_variable(v, p.base);
        for (const DesignVariable& earlier : p.variables) {
            if (earlier.path.text() == variable.path.text()) {
                throw InputError("--vary", v, variable.path.text() + " is already varied by --vary " + earlier.setting);
            }
        }
        p.variables.push_back(std::move(variable));
    }
    p.maximize = !q.maximize.empty();
    p.objective = quantity_column(p.maximize ? q.maximize : q.minimize, p.columns, p.maximize ? "--maximize" : "--minimize");
    for (const std::string& c : q.constraints) p.constraints.push_back(parse_design_constraint(c, p.columns));
    return p;
}

}  // namespace vi
