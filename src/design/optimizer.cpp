#include "design/optimizer.hpp"

#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <stdexcept>

namespace vi {
namespace {

// Both stages work on u in [0, 1]^n, x = low + u (high - low): variables of any unit and size then
// have steps and tolerances of one scale.
class Search {
public:
    Search(const DesignProblem& p, const std::function<void(const DesignEvaluation&)>& progress)
        : p_(p), progress_(progress), sign_(p.maximize ? -1.0 : 1.0) {}

    // The merit of u: the signed objective; a failed design is worse than every one seen; with
    // `penalise` (the global stage) a broken constraint makes the design worse than every one seen
    // by its relative violation (COBYLA, the local stage, is given the constraints themselves).
    double merit(const std::vector<double>& u, const char* stage, bool penalise) {
        const DesignEvaluation& e = evaluate(u, stage);
        if (e.feasible) return sign_ * *e.outcome.objective;
        const double base = worst_.value_or(0.0);
        if (!e.outcome.ok() || !e.outcome.objective) return base + 1.0 + std::abs(base);
        if (!penalise) return sign_ * *e.outcome.objective;
        const double value = std::max(base, sign_ * *e.outcome.objective);
        return value + (1.0 + std::abs(value)) * violation(e.outcome);
    }

    // Constraint k of the local stage at u: its relative violation (<= 0 where it holds).
    double constraint(const std::vector<double>& u, std::size_t k) {
        const DesignEvaluation& e = evaluate(u, "local");
        if (!e.outcome.ok() || !e.outcome.constraints[k]) return 1.0;
        const DesignConstraint& c = p_.constraints[k];
        return c.violation(*e.outcome.constraints[k]) / scale(c);
    }

    [[nodiscard]] std::vector<double> to_x(const std::vector<double>& u) const {
        std::vector<double> x(u.size());
        for (std::size_t i = 0; i < u.size(); ++i) {
            const DesignVariable& v = p_.variables[i];
            x[i] = std::clamp(v.low + u[i] * (v.high - v.low), v.low, v.high);
        }
        return x;
    }

    OptimizeResult result;
    std::exception_ptr error;  // a stop (or a bug) inside a callback, rethrown after NLopt returns

private:
    static double scale(const DesignConstraint& c) { return c.bound != 0.0 ? std::abs(c.bound) : 1.0; }

    [[nodiscard]] double violation(const DesignOutcome& o) const {
        double sum = 0.0;
        for (std::size_t k = 0; k < o.constraints.size(); ++k) {
            sum += o.constraints[k] ? std::max(0.0, p_.constraints[k].violation(*o.constraints[k]) / scale(p_.constraints[k]))
                                    : 1.0;
        }
        return sum;
    }

    // Computes u once: NLopt's stages may ask for the same design twice (the local start).
    const DesignEvaluation& evaluate(const std::vector<double>& u, const char* stage) {
        if (auto it = cache_.find(u); it != cache_.end()) return result.evaluations[it->second];
        DesignEvaluation e;
        e.index = result.evaluations.size();
        e.stage = stage;
        e.x = to_x(u);
        e.outcome = evaluate_design(p_, e.x);
        e.feasible = e.outcome.feasible(p_);
        if (e.outcome.ok() && e.outcome.objective) {
            const double m = sign_ * *e.outcome.objective;
            worst_ = std::max(worst_.value_or(m), m);
        }
        if (result.best) e.best = result.evaluations[*result.best].outcome.objective;
        if (e.feasible && (!e.best || sign_ * *e.outcome.objective < sign_ * *e.best)) {
            result.best = e.index;
            e.best = e.outcome.objective;
        }
        result.evaluations.push_back(std::move(e));
        cache_[u] = result.evaluations.size() - 1;
        if (progress_) progress_(result.evaluations.back());
        return result.evaluations.back();
    }

    const DesignProblem& p_;
    const std::function<void(const DesignEvaluation&)>& progress_;
    double sign_;
    std::optional<double> worst_;  // the largest signed objective of any design that has one
    std::map<std::vector<double>, std::size_t> cache_;
};

struct Callback {
    Search* search;
    nlopt_opt opt;
    const char* stage;
    bool penalise = false;
    std::size_t constraint = 0;
};

double objective_fn(unsigned n, const double* u, double*, void* data) {
    auto* cb = static_cast<Callback*>(data);
    try {
        return cb->search->merit(std::vector<double>(u, u + n), cb->stage, cb->penalise);
    } catch (...) {
        cb->search->error = std::current_exception();
        nlopt_force_stop(cb->opt);
        return 0.0;
    }
}

double constraint_fn(unsigned n, const double* u, double*, void* data) {
    auto* cb = static_cast<Callback*>(data);
    try {
        return cb->search->constraint(std::vector<double>(u, u + n), cb->constraint);
    } catch (...) {
        cb->search->error = std::current_exception();
        nlopt_force_stop(cb->opt);
        return 0.0;
    }
}

std::string why_ended(nlopt_result r, const char* budget) {
    switch (r) {
        case NLOPT_MAXEVAL_REACHED: return std::string("its evaluations were spent (") + budget + ")";
        case NLOPT_XTOL_REACHED: return "converged: the last steps moved every variable by less than the x tolerance";
        case NLOPT_FTOL_REACHED: return "converged: the objective stopped changing";
        case NLOPT_SUCCESS: return "converged";
        case NLOPT_ROUNDOFF_LIMITED: return "stopped by roundoff (the objective is flat or noisy at this scale)";
        case NLOPT_FORCED_STOP: return "stopped";
        default: return std::string("NLopt failed (") + nlopt_result_to_string(r) + ")";
    }
}

// RAII for an nlopt_opt.
struct Optimizer {
    explicit Optimizer(nlopt_algorithm a, unsigned n) : opt(nlopt_create(a, n)) {
        if (!opt) throw std::runtime_error("optimize: NLopt could not create its optimiser");
    }
    ~Optimizer() { nlopt_destroy(opt); }
    Optimizer(const Optimizer&) = delete;
    Optimizer& operator=(const Optimizer&) = delete;
    nlopt_opt opt;
};

}  // namespace

OptimizeResult optimize_design(const DesignProblem& p, const OptimizeOptions& o,
                               const std::function<void(const DesignEvaluation&)>& progress) {
    const unsigned n = static_cast<unsigned>(p.variables.size());
    if (n == 0) throw std::invalid_argument("optimize_design: no variables");
    if (o.max_evaluations < 2) throw std::invalid_argument("optimize_design: max_evaluations below 2");
    const int global = o.global_evaluations > 0 ? std::min(o.global_evaluations, o.max_evaluations - 1)
                                                : std::max(1, o.max_evaluations / 2);
    Search search(p, progress);
    const std::vector<double> lower(n, 0.0), upper(n, 1.0);

    {
        Optimizer g(NLOPT_GN_DIRECT_L, n);
        Callback cb{&search, g.opt, "global", true, 0};
        nlopt_set_lower_bounds(g.opt, lower.data());
        nlopt_set_upper_bounds(g.opt, upper.data());
        nlopt_set_min_objective(g.opt, objective_fn, &cb);
        nlopt_set_maxeval(g.opt, global);
        std::vector<double> u(n, 0.5);
        double value = 0.0;
        const nlopt_result r = nlopt_optimize(g.opt, u.data(), &value);
        if (search.error) std::rethrow_exception(search.error);
        search.result.global_end = why_ended(r, "the global share of --max-evals, --global-evals");
    }

    const int left = o.max_evaluations - static_cast<int>(search.result.evaluations.size());
    if (left <= 0) {
        search.result.local_end = "not run: no evaluations left (--max-evals)";
        return std::move(search.result);
    }
    // Start from the best feasible design, else from the best merit (the least bad).
    std::size_t start = 0;
    if (search.result.best) {
        start = *search.result.best;
    } else {
        double lowest = std::numeric_limits<double>::infinity();
        for (const DesignEvaluation& e : search.result.evaluations) {
            if (!e.outcome.ok() || !e.outcome.objective) continue;
            const double m = (p.maximize ? -1.0 : 1.0) * *e.outcome.objective;
            if (m < lowest) {
                lowest = m;
                start = e.index;
            }
        }
    }
    std::vector<double> u(n);
    for (unsigned i = 0; i < n; ++i) {
        const DesignVariable& v = p.variables[i];
        u[i] = (search.result.evaluations[start].x[i] - v.low) / (v.high - v.low);
    }
    Optimizer l(p.constraints.empty() ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA, n);
    Callback cb{&search, l.opt, "local", false, 0};
    std::vector<Callback> constraint_cbs(p.constraints.size(), Callback{&search, l.opt, "local", false, 0});
    nlopt_set_lower_bounds(l.opt, lower.data());
    nlopt_set_upper_bounds(l.opt, upper.data());
    nlopt_set_min_objective(l.opt, objective_fn, &cb);
    for (std::size_t k = 0; k < p.constraints.size(); ++k) {
        constraint_cbs[k].constraint = k;
        nlopt_add_inequality_constraint(l.opt, constraint_fn, &constraint_cbs[k], 0.0);
    }
    // The first step: about the spacing of the global stage's samples around the start.
    const double step = std::clamp(std::pow(static_cast<double>(global), -1.0 / n), 1e-3, 0.25);
    nlopt_set_initial_step1(l.opt, step);
    nlopt_set_xtol_abs1(l.opt, o.x_tolerance);
    nlopt_set_maxeval(l.opt, left);
    double value = 0.0;
    const nlopt_result r = nlopt_optimize(l.opt, u.data(), &value);
    if (search.error) std::rethrow_exception(search.error);
    search.result.local_end = why_ended(r, "--max-evals");
    return std::move(search.result);
}

}  // namespace vi
