#include "dynamics/piecewise_linear_form.hpp"

#include <string>
#include <type_traits>
#include <variant>

#include "model/input_error.hpp"

namespace vi {

PiecewiseLinearProblem piecewise_linear_form(const TransientProblem& p) {
    if (const ForceElement* e = first_nonlinear(p.forces)) {
        throw InputError("solver.method: the exact solver needs piecewise-linear forces, and " + e->name() + " (" +
                         e->kind() + ") is not; use method = \"cvode\" or \"auto\"");
    }
    PiecewiseLinearProblem out;
    out.M = Eigen::MatrixXd(p.M);
    out.K = Eigen::MatrixXd(p.K);
    out.alpha = p.alpha;
    out.beta = p.beta;
    const int n = p.size();
    for (std::size_t i = 0; i < p.forces.size(); ++i) {
        const ForceElement& e = *p.forces[i];
        const bool closed0 = i < p.modes0.size() && p.modes0[i] != 0;
        std::visit(
            [&](const auto& term) {
                using T = std::decay_t<decltype(term)>;
                if constexpr (std::is_same_v<T, UnilateralSpringDamper>) {
                    out.contacts.push_back(
                        {e.name(), term.dof, term.sign, term.surface, term.stiffness, term.damping, e.position()});
                    out.active0.push_back(closed0);
                } else {
                    LoadTerm l;
                    l.shape = Eigen::VectorXd::Zero(n);
                    for (std::size_t k = 0; k < term.dofs.size(); ++k) l.shape[term.dofs[k]] += term.weights[k];
                    l.amplitude = term.amplitude;
                    l.time = term.time;
                    out.loads.push_back(std::move(l));
                }
            },
            e.linear_form()->term);
    }
    if (p.modes0.empty()) out.active0.clear();
    out.q0 = p.q0;
    out.v0 = p.v0;
    out.watched_dof = p.watched_dof;
    out.t_end = p.t_end;
    out.output_step = p.output_step;
    return out;
}

}  // namespace vi
