#include "design/optimizer.hpp"

#include <nlopt.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <stdexcept>

#include "model/run_control.hpp"

namespace vi {
namespace {

// Where one pass of the search gets a design's outcome.
class Oracle {
public:
    virtual ~Oracle() = default;
    // The outcome of x, or nullptr when the pass must go on without it (a look-ahead's guess).
    virtual const DesignOutcome* outcome(const std::vector<double>& x) = 0;
    // True once a look-ahead has the guesses it wants: the pass stops there.
    [[nodiscard]] virtual bool enough() const { return false; }
    // True once the pass has gone on without an outcome (its path since rests on guesses).
    [[nodiscard]] virtual bool guessed() const { return false; }
};

// One pass of both stages, on u in [0, 1]^n, x = low + u (high - low): variables of any unit and
// size then have steps and tolerances of one scale.
class Pass {
public:
    Pass(const DesignProblem& p, Oracle& oracle, const std::function<void(const DesignEvaluation&)>& progress)
        : p_(p), oracle_(oracle), progress_(progress), sign_(p.maximize ? -1.0 : 1.0) {}

    // The merit of u: the signed objective; a failed design is worse than every one seen; with
    // `penalise` (the global stage) a broken constraint makes the design worse than every one seen
    // by its relative violation (COBYLA, the local stage, is given the constraints themselves).
    double merit(const std::vector<double>& u, const char* stage, bool penalise) {
        const DesignEvaluation* e = evaluate(u, stage);
        if (!e) return guess(u, [&](const DesignEvaluation& n) { return unpenalised(n); });
        if (e->feasible) return sign_ * *e->outcome.objective;
        const double base = worst_.value_or(0.0);
        if (!e->outcome.ok() || !e->outcome.objective) return base + 1.0 + std::abs(base);
        if (!penalise) return sign_ * *e->outcome.objective;
        const double value = std::max(base, sign_ * *e->outcome.objective);
        return value + (1.0 + std::abs(value)) * violation(e->outcome);
    }

    // Constraint k of the local stage at u: its relative violation (<= 0 where it holds).
    double constraint(const std::vector<double>& u, std::size_t k) {
        const DesignEvaluation* e = evaluate(u, "local");
        if (!e) return guess(u, [&](const DesignEvaluation& n) { return relative(n.outcome, k); });
        return relative(e->outcome, k);
    }

    [[nodiscard]] std::vector<double> to_x(const std::vector<double>& u) const {
        std::vector<double> x(u.size());
        for (std::size_t i = 0; i < u.size(); ++i) {
            const DesignVariable& v = p_.variables[i];
            x[i] = std::clamp(v.low + u[i] * (v.high - v.low), v.low, v.high);
        }
        return x;
    }

    [[nodiscard]] const Oracle& oracle() const { return oracle_; }

    OptimizeResult result;
    std::exception_ptr error;  // a stop (or a bug) inside a callback, rethrown after NLopt returns

private:
    static double scale(const DesignConstraint& c) { return c.bound != 0.0 ? std::abs(c.bound) : 1.0; }

    [[nodiscard]] double violation(const DesignOutcome& o) const {
        double sum = 0.0;
        for (std::size_t k = 0; k < o.constraints.size(); ++k) sum += std::max(0.0, relative(o, k));
        return sum;
    }

    [[nodiscard]] double relative(const DesignOutcome& o, std::size_t k) const {
        if (!o.ok() || !o.constraints[k]) return 1.0;
        return p_.constraints[k].violation(*o.constraints[k]) / scale(p_.constraints[k]);
    }

    [[nodiscard]] double unpenalised(const DesignEvaluation& e) const {
        if (e.outcome.ok() && e.outcome.objective) return sign_ * *e.outcome.objective;
        const double base = worst_.value_or(0.0);
        return base + 1.0 + std::abs(base);
    }

    // A look-ahead's stand-in for a design not computed yet: the value at the nearest design of
    // this pass (in DIRECT, the centre of the box being divided). Only its guesses depend on it.
    template <class Value>
    double guess(const std::vector<double>& u, Value value) const {
        if (result.evaluations.empty()) return 0.0;
        std::size_t nearest = 0;
        double closest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < us_.size(); ++i) {
            double d = 0.0;
            for (std::size_t j = 0; j < u.size(); ++j) d += (u[j] - us_[i][j]) * (u[j] - us_[i][j]);
            if (d < closest) {
                closest = d;
                nearest = i;
            }
        }
        return value(result.evaluations[nearest]);
    }

    // Records u once: the stages may ask for the same design twice (the local start). nullptr
    // when the oracle has no outcome (a look-ahead's guess, never recorded).
    const DesignEvaluation* evaluate(const std::vector<double>& u, const char* stage) {
        const std::vector<double> x = to_x(u);
        const std::vector<std::uint64_t> key = design_key(x);
        if (auto it = seen_.find(key); it != seen_.end()) return it->second ? &result.evaluations[*it->second] : nullptr;
        const DesignOutcome* outcome = oracle_.outcome(x);
        if (!outcome) {
            seen_[key] = std::nullopt;
            return nullptr;
        }
        DesignEvaluation e;
        e.index = result.evaluations.size();
        e.stage = stage;
        e.x = x;
        e.outcome = *outcome;
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
        us_.push_back(u);
        seen_[key] = result.evaluations.size() - 1;
        if (progress_) progress_(result.evaluations.back());
        return &result.evaluations.back();
    }

    const DesignProblem& p_;
    Oracle& oracle_;
    const std::function<void(const DesignEvaluation&)>& progress_;
    double sign_;
    std::optional<double> worst_;  // the largest signed objective of any design that has one
    std::vector<std::vector<double>> us_;  // u of every evaluation
    std::map<std::vector<std::uint64_t>, std::optional<std::size_t>> seen_;
};

struct Callback {
    Pass* pass;
    nlopt_opt opt;
    const char* stage;
    bool penalise = false;
    std::size_t constraint = 0;
};

template <class F>
double guarded(Callback* cb, F f) {
    try {
        const double v = f();
        if (cb->pass->oracle().enough()) nlopt_force_stop(cb->opt);
        return v;
    } catch (...) {
        cb->pass->error = std::current_exception();
        nlopt_force_stop(cb->opt);
        return 0.0;
    }
}

double objective_fn(unsigned n, const double* u, double*, void* data) {
    auto* cb = static_cast<Callback*>(data);
    return guarded(cb, [&] { return cb->pass->merit(std::vector<double>(u, u + n), cb->stage, cb->penalise); });
}

double constraint_fn(unsigned n, const double* u, double*, void* data) {
    auto* cb = static_cast<Callback*>(data);
    return guarded(cb, [&] { return cb->pass->constraint(std::vector<double>(u, u + n), cb->constraint); });
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

// Both stages, each design's outcome from `oracle`. A look-ahead pass stops once its oracle has
// enough guesses, and after the global stage if that went on without an outcome (the local
// stage's start would rest on guesses).
OptimizeResult run_stages(const DesignProblem& p, const OptimizeOptions& o, Oracle& oracle,
                          const std::function<void(const DesignEvaluation&)>& progress) {
    const unsigned n = static_cast<unsigned>(p.variables.size());
    const int global = o.global_evaluations > 0 ? std::min(o.global_evaluations, o.max_evaluations - 1)
                                                : std::max(1, o.max_evaluations / 2);
    Pass pass(p, oracle, progress);
    const std::vector<double> lower(n, 0.0), upper(n, 1.0);
    {
        Optimizer g(NLOPT_GN_DIRECT_L, n);
        Callback cb{&pass, g.opt, "global", true, 0};
        nlopt_set_lower_bounds(g.opt, lower.data());
        nlopt_set_upper_bounds(g.opt, upper.data());
        nlopt_set_min_objective(g.opt, objective_fn, &cb);
        nlopt_set_maxeval(g.opt, global);
        std::vector<double> u(n, 0.5);
        double value = 0.0;
        const nlopt_result r = nlopt_optimize(g.opt, u.data(), &value);
        if (pass.error) std::rethrow_exception(pass.error);
        pass.result.global_end = why_ended(r, "the global share of --max-evals, --global-evals");
    }
    if (oracle.enough() || oracle.guessed()) return std::move(pass.result);

    const int left = o.max_evaluations - static_cast<int>(pass.result.evaluations.size());
    if (left <= 0) {
        pass.result.local_end = "not run: no evaluations left (--max-evals)";
        return std::move(pass.result);
    }
    // Start from the best feasible design, else from the best merit (the least bad).
    std::size_t start = 0;
    if (pass.result.best) {
        start = *pass.result.best;
    } else {
        double lowest = std::numeric_limits<double>::infinity();
        for (const DesignEvaluation& e : pass.result.evaluations) {
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
        u[i] = (pass.result.evaluations[start].x[i] - v.low) / (v.high - v.low);
    }
    Optimizer l(p.constraints.empty() ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA, n);
    Callback cb{&pass, l.opt, "local", false, 0};
    std::vector<Callback> constraint_cbs(p.constraints.size(), Callback{&pass, l.opt, "local", false, 0});
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
    if (pass.error) std::rethrow_exception(pass.error);
    pass.result.local_end = why_ended(r, "--max-evals");
    return std::move(pass.result);
}

// A look-ahead: the search replayed from the start on the designs known so far, going on past the
// first unknown design with guessed values, to list the next designs it would ask for.
class LookAhead : public Oracle {
public:
    LookAhead(const DesignStore& store, std::size_t want) : store_(store), want_(want) {}
    const DesignOutcome* outcome(const std::vector<double>& x) override {
        if (const DesignOutcome* d = store_.find(x)) return d;
        guesses.push_back(x);
        return nullptr;
    }
    [[nodiscard]] bool enough() const override { return guesses.size() >= want_; }
    [[nodiscard]] bool guessed() const override { return !guesses.empty(); }
    std::vector<std::vector<double>> guesses;  // in the order asked; the first is certain

private:
    const DesignStore& store_;
    std::size_t want_;
};

// The search's own oracle: a design not known is computed, together with the next ones a
// look-ahead expects, one per thread.
// A look-ahead replays the whole search so far, a cost that grows with the evaluations while a
// design's does not: once the replays have taken more than a tenth of the time spent computing,
// the search goes on one design at a time (same result, only slower).
class Computing : public Oracle {
public:
    Computing(const DesignProblem& p, const OptimizeOptions& o, DesignStore& store)
        : p_(p), o_(o), store_(store), look_ahead_(store.threads() > 1) {}
    const DesignOutcome* outcome(const std::vector<double>& x) override {
        if (const DesignOutcome* d = store_.find(x)) return d;
        using Clock = std::chrono::steady_clock;
        std::vector<std::vector<double>> batch{x};
        if (look_ahead_) {
            const auto t0 = Clock::now();
            LookAhead ahead(store_, static_cast<std::size_t>(store_.threads()));
            run_stages(p_, o_, ahead, {});
            // The replay sees what this search has seen, so its first unknown design is x.
            if (ahead.guesses.empty() || design_key(ahead.guesses.front()) != design_key(x)) {
                throw std::logic_error("optimize: the look-ahead left the search's path");
            }
            batch = std::move(ahead.guesses);
            replay_s_ += seconds_since(t0);
        }
        const auto t1 = Clock::now();
        store_.compute(batch);
        compute_s_ += seconds_since(t1);
        if (look_ahead_ && store_.batches() >= 4 && replay_s_ > 0.1 * compute_s_) {
            look_ahead_ = false;
            gave_up_after = store_.batches();
        }
        const DesignOutcome* d = store_.find(x);
        if (!d) throw std::logic_error("optimize: a computed design is missing");
        return d;
    }
    std::size_t gave_up_after = 0;  // batches before the look-ahead stopped; 0 while it runs
    [[nodiscard]] double replay_s() const { return replay_s_; }

private:
    const DesignProblem& p_;
    const OptimizeOptions& o_;
    DesignStore& store_;
    bool look_ahead_;
    double replay_s_ = 0.0, compute_s_ = 0.0;
};

}  // namespace

OptimizeResult optimize_design(const DesignProblem& p, const OptimizeOptions& o,
                               const std::function<void(const DesignEvaluation&)>& progress) {
    if (p.variables.empty()) throw std::invalid_argument("optimize_design: no variables");
    if (o.max_evaluations < 2) throw std::invalid_argument("optimize_design: max_evaluations below 2");
    DesignStore store(p, o.threads, o.computed);
    for (const ComputedDesign& d : o.known) {
        if (d.x.size() != p.variables.size() || d.outcome.constraints.size() != p.constraints.size()) {
            throw std::invalid_argument("optimize_design: a known design of another problem (its variables or constraints)");
        }
        store.add_known(d);
    }
    Computing oracle(p, o, store);
    OptimizeResult r = run_stages(p, o, oracle, progress);
    r.threads = store.threads();
    r.computed = store.computed();
    r.batches = store.batches();
    r.look_ahead_stopped_after = oracle.gave_up_after;
    r.look_ahead_s = oracle.replay_s();
    for (const DesignEvaluation& e : r.evaluations) r.reused += store.is_known(e.x) ? 1 : 0;
    r.unused_guesses = store.computed() - (r.evaluations.size() - r.reused);
    return r;
}

}  // namespace vi
