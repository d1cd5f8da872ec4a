#include "calibration/least_squares.hpp"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <numeric>
#include <stdexcept>

#include "model/parallel_for.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

// Ceres logs through glog, which writes every warning to stderr before InitGoogleLogging ("Logging
// before InitGoogleLogging() is written to STDERR", then a residual block's whole dump) and to
// files under /tmp after it. The fit reports its own outcome in one line, so glog is initialised
// here with everything below FATAL dropped and to stderr only (no log files). Someone who wants
// Ceres' log asks glog for it through its own environment variables (GLOG_minloglevel=0
// GLOG_logtostderr=1 ...): a variable that is set is left as it is.
void quiet_solver_logging() {
    static std::once_flag once;
    std::call_once(once, [] {
        if (!google::IsGoogleLoggingInitialized()) google::InitGoogleLogging("vibroimpact");
        if (std::getenv("GLOG_minloglevel") == nullptr) FLAGS_minloglevel = google::GLOG_FATAL;
        if (std::getenv("GLOG_logtostderr") == nullptr && std::getenv("GLOG_log_dir") == nullptr) FLAGS_logtostderr = true;
    });
}

// The residuals for Ceres, in scaled parameters z (x = z * scale).
class Residual {
public:
    explicit Residual(const LeastSquaresProblem& p) : p_(p) {}

    bool operator()(double const* const* z, double* r) const {
        if (stopped_) return false;
        std::vector<double> x(p_.params.size());
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = z[0][i] * p_.params[i].scale();
        ++calls_;
        try {
            p_.evaluate(x, r);
            // A residual that is not a finite number is a design the model cannot answer for: a
            // failed step, said here rather than by Ceres (which would dump the block to its log).
            return std::all_of(r, r + p_.residuals, [](double v) { return std::isfinite(v); });
        } catch (const StopRequested&) {
            stopped_ = true;  // Ceres is told by the iteration callback; nothing may unwind through it
            return false;
        } catch (const std::exception&) {
            return false;  // a design that cannot run: Ceres shrinks its step
        }
    }

    [[nodiscard]] bool stopped() const { return stopped_; }
    [[nodiscard]] int calls() const { return calls_; }

private:
    const LeastSquaresProblem& p_;
    mutable bool stopped_ = false;
    mutable int calls_ = 0;
};

// Ends the solve on a stop, and counts the iterations to the fit's progress (Ceres reports the
// start's evaluation as iteration 0: not one of the budget's).
class StopCallback final : public ceres::IterationCallback {
public:
    StopCallback(const Residual& r, const std::function<void(int, int)>& progress) : r_(r), progress_(progress) {}
    ceres::CallbackReturnType operator()(const ceres::IterationSummary& it) override {
        if (it.iteration > 0 && progress_) {
            ++counted_;
            progress_(1, 0);
        }
        return r_.stopped() || stop_flag().load() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
    }
    [[nodiscard]] int counted() const { return counted_; }

private:
    const Residual& r_;
    const std::function<void(int, int)>& progress_;
    int counted_ = 0;
};

// A Ceres problem over z with p's residuals (central differences) and bounds; the cost function is
// owned by the problem, the residual object by the cost function.
struct CeresSetup {
    ceres::Problem problem;
    Residual* residual = nullptr;
};

void set_up(CeresSetup& s, const LeastSquaresProblem& p, std::vector<double>& z) {
    quiet_solver_logging();
    const int n = static_cast<int>(p.params.size());
    s.residual = new Residual(p);
    auto* cost = new ceres::DynamicNumericDiffCostFunction<Residual, ceres::CENTRAL>(s.residual, ceres::TAKE_OWNERSHIP);
    cost->AddParameterBlock(n);
    cost->SetNumResiduals(p.residuals);
    s.problem.AddResidualBlock(cost, nullptr, z.data());
    for (int i = 0; i < n; ++i) {
        const FitParameter& q = p.params[static_cast<std::size_t>(i)];
        if (q.low) s.problem.SetParameterLowerBound(z.data(), i, *q.low / q.scale());
        if (q.high) s.problem.SetParameterUpperBound(z.data(), i, *q.high / q.scale());
    }
}

StartRun solve_from(const LeastSquaresProblem& p, const std::vector<double>& start, int max_iterations,
                    const std::function<void(int, int)>& progress) {
    const std::size_t n = p.params.size();
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; ++i) z[i] = start[i] / p.params[i].scale();
    CeresSetup s;
    set_up(s, p, z);
    StopCallback stop(*s.residual, progress);
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = max_iterations;
    so.num_threads = 1;
    // Converged when a step changes the cost by less than 1e-10 of it or the parameters by less than
    // 1e-8 of their scale: the intervals are read at the minimum, so stopping early would bias them.
    so.function_tolerance = 1e-10;
    so.parameter_tolerance = 1e-8;
    so.gradient_tolerance = 1e-14;
    so.minimizer_progress_to_stdout = false;
    so.logging_type = ceres::SILENT;
    so.callbacks.push_back(&stop);
    so.update_state_every_iteration = true;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &s.problem, &summary);
    if (s.residual->stopped() || stop_flag().load()) throw StopRequested(stop_signal());
    if (progress && max_iterations > stop.counted()) progress(0, max_iterations - stop.counted());
    StartRun run;
    run.start = start;
    run.converged = summary.termination_type == ceres::CONVERGENCE;
    run.message = summary.message;
    run.iterations = static_cast<int>(summary.iterations.size());
    run.simulations = s.residual->calls();
    // Ceres fails when it cannot evaluate the model and its Jacobian at an accepted point (a failed
    // trial step only shrinks the trust region): at the start, the start cannot run; later, the
    // last accepted point stands, not converged.
    const bool failed = summary.termination_type == ceres::FAILURE;
    const bool ran = std::isfinite(summary.final_cost) && (!failed || summary.iterations.size() > 1);
    run.cost = ran ? summary.final_cost : std::numeric_limits<double>::infinity();
    if (failed) {
        run.message = (ran ? "stopped: a design a difference step away from the last estimate could not run; bound the "
                             "parameters to designs that run ("
                           : "the model or its Jacobian cannot be computed at this start (") + summary.message + ")";
    }
    for (std::size_t i = 0; i < n; ++i) run.end.push_back(z[i] * p.params[i].scale());
    return run;
}

// Groups the converged ends into distinct minima, 0 for the best's: two ends are one minimum when
// their parameters agree within 1e-3 of their scale, or their costs within 1e-6 of the larger (a
// flat valley is one minimum however far apart its ends lie).
int group_minima(const LeastSquaresProblem& p, std::vector<StartRun>& runs, std::size_t best) {
    std::vector<std::size_t> order(runs.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return runs[a].cost < runs[b].cost; });
    std::rotate(order.begin(), std::find(order.begin(), order.end(), best), std::find(order.begin(), order.end(), best) + 1);
    std::vector<std::size_t> representative;
    for (std::size_t k : order) {
        StartRun& r = runs[k];
        if (!r.converged) continue;
        for (std::size_t g = 0; g < representative.size() && r.minimum < 0; ++g) {
            const StartRun& s = runs[representative[g]];
            double far = 0.0;
            for (std::size_t i = 0; i < p.params.size(); ++i) far = std::max(far, std::abs(r.end[i] - s.end[i]) / p.params[i].scale());
            const bool same_cost = std::abs(r.cost - s.cost) <= 1e-6 * std::max(r.cost, s.cost) + 1e-300;
            if (far < 1e-3 || same_cost) r.minimum = static_cast<int>(g);
        }
        if (r.minimum < 0) {
            r.minimum = static_cast<int>(representative.size());
            representative.push_back(k);
        }
    }
    return static_cast<int>(representative.size());
}

// The radical inverse of k in base b: the k-th point of a van der Corput sequence, in [0, 1).
double radical_inverse(std::size_t k, std::size_t b) {
    double f = 1.0, x = 0.0;
    for (; k > 0; k /= b) {
        f /= static_cast<double>(b);
        x += f * static_cast<double>(k % b);
    }
    return x;
}

// The Jacobian of the residuals at x in scaled parameters (Ceres' central differences, as the
// solve), the residuals there, and the model runs it took.
Eigen::MatrixXd scaled_jacobian(const LeastSquaresProblem& p, const std::vector<double>& x, std::vector<double>& res,
                                int& calls) {
    const int n = static_cast<int>(p.params.size());
    std::vector<double> z(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) z[static_cast<std::size_t>(i)] = x[static_cast<std::size_t>(i)] / p.params[static_cast<std::size_t>(i)].scale();
    CeresSetup s;
    set_up(s, p, z);
    double cost_value = 0.0;
    ceres::CRSMatrix crs;
    const bool ok = s.problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost_value, &res, nullptr, &crs);
    calls += s.residual->calls();
    if (s.residual->stopped() || stop_flag().load()) throw StopRequested(stop_signal());
    if (!ok) throw std::runtime_error("the Jacobian at the estimate could not be computed: a design a difference step away failed to run");
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(p.residuals, n);
    for (int row = 0; row < crs.num_rows; ++row) {
        for (int k = crs.rows[static_cast<std::size_t>(row)]; k < crs.rows[static_cast<std::size_t>(row) + 1]; ++k) {
            J(row, crs.cols[static_cast<std::size_t>(k)]) = crs.values[static_cast<std::size_t>(k)];
        }
    }
    return J;
}

const char* const kTooWeakly = "the data fix it too weakly (a singular value below 1e-3 of the largest)";

// Why the data cannot fix each parameter ("" when they can): the directions of J (in parameters
// scaled to their range or start) whose singular value is below 1e-3 of the largest (or that J does
// not reach: fewer residuals than parameters), and the parameters that take part in them. Not
// roundoff: the Jacobian comes from central differences of simulations whose trajectories carry a
// relative noise near 1e-10 (the modes are recomputed for every stiffness), so an exact trade-off (E
// and nu through E / (1 - nu^2)) shows up near 1e-4 (measured), never at 1e-16; the determined ones of
// the tests lie above 2e-2.
std::vector<std::string> undetermined_by(const Eigen::MatrixXd& J, const std::vector<FitParameter>& params) {
    const int n = static_cast<int>(params.size());
    std::vector<std::string> out(static_cast<std::size_t>(n));
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
    const Eigen::VectorXd sv = svd.singularValues();
    const double top = sv.size() > 0 ? sv[0] : 0.0;
    for (int j = 0; j < n; ++j) {
        const double value = j < sv.size() ? sv[j] : 0.0;
        if (value > 1e-3 * top && top > 0.0) continue;
        for (int i = 0; i < n; ++i) {
            if (std::abs(svd.matrixV()(i, j)) < 0.1) continue;
            std::string why = J.col(i).norm() <= 1e-12 * std::max(top, 1e-300) ? "the data do not depend on it"
                                                                                  : "it trades off with";
            if (why != "the data do not depend on it") {
                std::string with;
                for (int k = 0; k < n; ++k) {
                    if (k != i && std::abs(svd.matrixV()(k, j)) >= 0.1) with.append(" ").append(params[static_cast<std::size_t>(k)].name());
                }
                why = with.empty() ? kTooWeakly : why + with;
            }
            std::string& slot = out[static_cast<std::size_t>(i)];
            if (slot.empty() || slot == kTooWeakly) slot = why;
        }
    }
    return out;
}

const char* const kNotFinite = "the residuals or their Jacobian at the estimate are not finite numbers";
const char* const kNoNoiseEstimate =
    "the residuals are zero to double precision, so they estimate no noise level and no uncertainty (a sigma column "
    "in the data gives one)";
const char* const kVarianceNotFinite =
    "its variance is not a finite positive number in double precision (the data's dependence on it underflows or "
    "overflows)";

// The covariance s2 (Jk^T Jk)^-1 of the parameters still determined (r.undetermined empty), in
// scaled parameters; their indices in `kept`. A variance that comes out not finite or not positive
// (a Jacobian column that underflows: J^T J rounds to zero), with s2 > 0, is no uncertainty: that
// parameter is marked undetermined and the rest computed again (at most once per parameter).
Eigen::MatrixXd determined_covariance(const Eigen::MatrixXd& J, double s2, FitResult& r, std::vector<int>& kept) {
    const int n = static_cast<int>(J.cols());
    for (int round = 0; round <= n; ++round) {
        kept.clear();
        for (int i = 0; i < n; ++i) {
            if (r.undetermined[static_cast<std::size_t>(i)].empty()) kept.push_back(i);
        }
        const int m = static_cast<int>(kept.size());
        Eigen::MatrixXd Jk(J.rows(), m);
        for (int a = 0; a < m; ++a) Jk.col(a) = J.col(kept[static_cast<std::size_t>(a)]);
        const Eigen::MatrixXd cov = s2 * (Jk.transpose() * Jk).ldlt().solve(Eigen::MatrixXd::Identity(m, m));
        int bad = -1;
        for (int a = 0; a < m && bad < 0; ++a) {
            const double v = cov(a, a);
            if (!std::isfinite(v) || !(v > 0.0)) bad = a;
        }
        if (bad < 0) return cov;
        r.undetermined[static_cast<std::size_t>(kept[static_cast<std::size_t>(bad)])] = kVarianceNotFinite;
    }
    kept.clear();
    return Eigen::MatrixXd(0, 0);
}

// The estimate's uncertainty from the Jacobian there.
void add_uncertainty(const LeastSquaresProblem& p, FitResult& r) {
    const int n = static_cast<int>(p.params.size());
    const int samples = p.residuals;
    std::vector<double> res;
    const Eigen::MatrixXd J = scaled_jacobian(p, r.estimate, res, r.simulations);
    r.cost = 0.0;
    for (double v : res) r.cost += 0.5 * v * v;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.std_error.assign(static_cast<std::size_t>(n), nan);
    r.correlation = Eigen::MatrixXd::Constant(n, n, nan);
    r.ci_low.assign(static_cast<std::size_t>(n), nan);
    r.ci_high.assign(static_cast<std::size_t>(n), nan);
    if (!J.allFinite() || !std::isfinite(r.cost)) {
        // Nothing can be said about any parameter: the fit reports that, never an interval.
        r.undetermined.assign(static_cast<std::size_t>(n), kNotFinite);
        r.converged = false;
        r.message = std::string(kNotFinite) + ", so no parameter's uncertainty can be given";
        return;
    }
    // The covariance s2 (J^T J)^-1 does not depend on how the residuals were scaled.
    double ssr_scaled = 0.0;
    for (double v : res) ssr_scaled += v * v;
    const double s2 = p.sigma_known ? 1.0 : ssr_scaled / std::max(1, samples - n);
    if (!(s2 >= std::numeric_limits<double>::min())) {
        // Residuals that vanish (or underflow) estimate no noise: a zero interval would claim a
        // perfect estimate the data cannot give.
        r.undetermined.assign(static_cast<std::size_t>(n), kNoNoiseEstimate);
        return;
    }
    r.undetermined = undetermined_by(J, p.params);
    std::vector<int> kept;
    const Eigen::MatrixXd cov = determined_covariance(J, s2, r, kept);
    const int m = static_cast<int>(kept.size());
    for (int a = 0; a < m; ++a) {
        const int i = kept[static_cast<std::size_t>(a)];
        r.std_error[static_cast<std::size_t>(i)] = std::sqrt(cov(a, a)) * p.params[static_cast<std::size_t>(i)].scale();
        for (int b = 0; b < m; ++b) {
            r.correlation(i, kept[static_cast<std::size_t>(b)]) = cov(a, b) / std::sqrt(cov(a, a) * cov(b, b));
        }
    }
    for (int i = 0; i < n; ++i) {
        const std::size_t u = static_cast<std::size_t>(i);
        r.ci_low[u] = r.estimate[u] - 1.96 * r.std_error[u];
        r.ci_high[u] = r.estimate[u] + 1.96 * r.std_error[u];
    }
}

}  // namespace

Eigen::MatrixXd jacobian_at(const LeastSquaresProblem& p, const std::vector<double>& x, int& calls) {
    std::vector<double> res;
    Eigen::MatrixXd J = scaled_jacobian(p, x, res, calls);
    for (std::size_t i = 0; i < p.params.size(); ++i) J.col(static_cast<Eigen::Index>(i)) /= p.params[i].scale();
    return J;
}

std::size_t overflowing_residual(const std::vector<double>& weighted) {
    double sum = 0.0;
    std::size_t largest = 0;
    for (std::size_t k = 0; k < weighted.size(); ++k) {
        sum += weighted[k] * weighted[k];
        if (!(std::abs(weighted[k]) <= std::abs(weighted[largest]))) largest = k;
    }
    return std::isfinite(sum) ? weighted.size() : largest;
}

Eigen::MatrixXd covariance(const FitResult& r) {
    const Eigen::Index n = static_cast<Eigen::Index>(r.std_error.size());
    Eigen::MatrixXd v(n, n);
    for (Eigen::Index a = 0; a < n; ++a) {
        for (Eigen::Index b = 0; b < n; ++b) {
            v(a, b) = r.correlation(a, b) * r.std_error[static_cast<std::size_t>(a)] * r.std_error[static_cast<std::size_t>(b)];
        }
    }
    return v;
}

void set_covariance(FitResult& r, const Eigen::MatrixXd& v) {
    for (Eigen::Index a = 0; a < v.rows(); ++a) {
        const std::size_t u = static_cast<std::size_t>(a);
        if (!r.undetermined[u].empty()) continue;
        r.std_error[u] = std::sqrt(v(a, a));
        r.ci_low[u] = r.estimate[u] - 1.96 * r.std_error[u];
        r.ci_high[u] = r.estimate[u] + 1.96 * r.std_error[u];
        for (Eigen::Index b = 0; b < v.cols(); ++b) {
            if (r.undetermined[static_cast<std::size_t>(b)].empty()) r.correlation(a, b) = v(a, b) / std::sqrt(v(a, a) * v(b, b));
        }
    }
}

std::vector<std::vector<double>> start_points(const std::vector<FitParameter>& params, int count) {
    static constexpr std::size_t kPrimes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71};
    std::vector<std::vector<double>> out;
    for (int k = 0; k < count; ++k) {
        std::vector<double> x;
        for (std::size_t i = 0; i < params.size(); ++i) {
            const FitParameter& p = params[i];
            if (k == 0) {
                x.push_back(p.start);
                continue;
            }
            // Halton points from index 1 on (index 0 is the corner 0, ..., 0); beyond 20 parameters
            // the bases repeat with an offset index, which keeps the points distinct if less even.
            const std::size_t base = kPrimes[i % std::size(kPrimes)];
            const double u = radical_inverse(static_cast<std::size_t>(k) + i / std::size(kPrimes) * 7, base);
            if (p.low && p.high) {
                const bool log = *p.low > 0.0 && *p.high >= 100.0 * *p.low;
                x.push_back(log ? *p.low * std::pow(*p.high / *p.low, u) : *p.low + u * (*p.high - *p.low));
            } else {
                double v = p.start * std::pow(2.0, 2.0 * u - 1.0);
                if (p.low) v = std::max(v, *p.low);
                if (p.high) v = std::min(v, *p.high);
                x.push_back(v);
            }
        }
        out.push_back(std::move(x));
    }
    return out;
}

FitResult fit_least_squares(const LeastSquaresProblem& p, const FitOptions& o) {
    const std::vector<std::vector<double>> starts = start_points(p.params, std::max(1, o.starts));
    std::vector<StartRun> runs(starts.size());
    parallel_for(starts.size(), starts.size() == 1 ? 1 : o.threads,
                 [&](std::size_t k) { runs[k] = solve_from(p, starts[k], o.max_iterations, o.progress); });
    if (stop_flag().load()) throw StopRequested(stop_signal());
    std::size_t best = 0;
    for (std::size_t k = 1; k < runs.size(); ++k) {
        // The lowest cost; among equal costs a converged run, then the earliest.
        const bool lower = runs[k].cost < runs[best].cost;
        const bool tie_better = runs[k].cost == runs[best].cost && runs[k].converged && !runs[best].converged;
        if (lower || tie_better) best = k;
    }
    FitResult r;
    r.best = best;
    r.estimate = runs[best].end;
    r.converged = runs[best].converged;
    r.message = runs[best].message;
    r.iterations = runs[best].iterations;
    for (const StartRun& run : runs) r.simulations += run.simulations;
    if (!std::isfinite(runs[best].cost)) throw std::runtime_error("the model cannot run at any start: " + runs[best].message);
    r.distinct_minima = group_minima(p, runs, best);
    r.starts = std::move(runs);
    r.sigma_from_residuals = !p.sigma_known;
    add_uncertainty(p, r);
    return r;
}

}  // namespace vi
