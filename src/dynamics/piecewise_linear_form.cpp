#include "dynamics/piecewise_linear_form.hpp"

#include <memory>
#include <string>
#include <type_traits>
#include <variant>

#include "forces/kelvin_voigt_contact.hpp"
#include "forces/point_load_element.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

// The fields both forms share: the start and what to record.
template <class From, class To>
void copy_start_and_output(const From& p, To& out) {
    out.q0 = p.q0;
    out.v0 = p.v0;
    out.tip_dof = p.tip_dof;
    out.t_end = p.t_end;
    out.output_step = p.output_step;
}

}  // namespace

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
                    out.contacts.push_back({term.dof, term.sign, term.surface, term.stiffness, term.damping, e.position()});
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
    copy_start_and_output(p, out);
    return out;
}

TransientProblem transient_problem_of(const PiecewiseLinearProblem& p) {
    TransientProblem out;
    out.M = p.M.sparseView();
    out.K = p.K.sparseView();
    out.alpha = p.alpha;
    out.beta = p.beta;
    for (std::size_t k = 0; k < p.contacts.size(); ++k) {
        const ContactElement& c = p.contacts[k];
        out.forces.push_back(std::make_shared<KelvinVoigtContact>("supports[" + std::to_string(k) + "]", c.dof, c.sign,
                                                                  c.surface, c.stiffness, c.damping, c.x));
        out.modes0.push_back(k < p.active0.size() && p.active0[k] ? 1 : 0);
    }
    for (std::size_t k = 0; k < p.loads.size(); ++k) {
        const LoadTerm& l = p.loads[k];
        std::vector<int> dofs;
        std::vector<double> weights;
        for (Eigen::Index i = 0; i < l.shape.size(); ++i) {
            if (l.shape[i] != 0.0) {
                dofs.push_back(static_cast<int>(i));
                weights.push_back(l.shape[i]);
            }
        }
        out.forces.push_back(std::make_shared<PointLoadElement>("loads[" + std::to_string(k) + "]", std::move(dofs),
                                                         std::move(weights), l.amplitude, l.time, -1.0));
        out.modes0.push_back(0);
    }
    if (p.active0.empty()) out.modes0.clear();
    copy_start_and_output(p, out);
    return out;
}

}  // namespace vi
