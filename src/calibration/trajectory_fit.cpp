#include "calibration/trajectory_fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "impacts/simulation.hpp"
#include "io/range_spec.hpp"
#include "model/case_checks.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

// The step scale of parameter i: its bound range, else the size of its start.
double scale_of(const FitParameter& p) {
    return p.low && p.high ? *p.high - *p.low : std::abs(p.start);
}

// Linear interpolation of (t, v) at x (t ascending, x within [t.front(), t.back()]).
double interpolate(const std::vector<double>& t, const std::vector<double>& v, double x) {
    const auto it = std::lower_bound(t.begin(), t.end(), x);
    if (it == t.begin()) return v.front();
    if (it == t.end()) return v.back();
    const std::size_t k = static_cast<std::size_t>(it - t.begin());
    const double w = (x - t[k - 1]) / (t[k] - t[k - 1]);
    return v[k - 1] + w * (v[k] - v[k - 1]);
}

// The residual of the whole record for Ceres, in scaled parameters z (theta = z * scale).
class Residual {
public:
    // Without a per-sample sigma the residuals are divided by the record's largest |value|: Ceres'
    // tolerances are absolute, and a record in metres (1e-6) would look converged at the start.
    Residual(const Case& base, const std::vector<FitParameter>& params, const MeasuredTrajectory& data)
        : base_(base), params_(params), data_(data) {
        for (double v : data.value) unit_ = std::max(unit_, std::abs(v));
        if (!(unit_ > 0.0)) unit_ = 1.0;
    }

    bool operator()(double const* const* z, double* r) const {
        if (stopped_) return false;
        std::vector<double> x(params_.size());
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = z[0][i] * scale_of(params_[i]);
        ++calls_;
        try {
            const std::vector<double> m = model_trajectory(base_, params_, x, data_.t, data_.column);
            for (std::size_t k = 0; k < m.size(); ++k) {
                r[k] = (m[k] - data_.value[k]) / (data_.sigma.empty() ? unit_ : data_.sigma[k]);
            }
            return true;
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
    const Case& base_;
    const std::vector<FitParameter>& params_;
    const MeasuredTrajectory& data_;
    double unit_ = 0.0;
    mutable bool stopped_ = false;
    mutable int calls_ = 0;
};

class StopCallback final : public ceres::IterationCallback {
public:
    explicit StopCallback(const Residual& r) : r_(r) {}
    ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
        return r_.stopped() || stop_flag().load() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
    }

private:
    const Residual& r_;
};

}  // namespace

FitParameter parse_fit_parameter(const std::string& text, const Case& c) {
    const auto fail = [&](const std::string& reason) { return InputError("--fit " + text + ": " + reason); };
    const std::size_t eq = text.find('=');
    FitParameter p;
    p.setting = text;
    try {
        p.path = resolve_case_path(text.substr(0, eq), c);
    } catch (const InputError& e) {
        throw fail(e.what());
    }
    if (is_integer_path(p.path)) throw fail(p.path.text() + " takes whole numbers, which a least-squares fit cannot vary");
    p.start = get_case_value(c, p.path);
    if (eq != std::string::npos) {
        const auto bounds = parse_bounds(text.substr(eq + 1), case_path_dimension(p.path));
        if (!bounds) throw fail("expected PATH or PATH=LOW:HIGH, two finite numbers (SI, or with units as in case files)");
        if (!(bounds->first < bounds->second)) throw fail("LOW must be below HIGH");
        p.low = bounds->first;
        p.high = bounds->second;
        if (p.start < *p.low || p.start > *p.high) {
            throw fail("the case's value " + std::to_string(p.start) + " (the start) lies outside the bounds");
        }
    } else if (p.start == 0.0) {
        throw fail("the case's value is 0: give bounds PATH=LOW:HIGH so the fit has a scale to step by");
    }
    return p;
}

std::vector<double> model_trajectory(const Case& base, const std::vector<FitParameter>& params,
                                     const std::vector<double>& x, const std::vector<double>& times,
                                     const std::string& column) {
    Case c = base;
    for (std::size_t i = 0; i < params.size(); ++i) set_case_value(c, params[i].path, x[i]);
    c.solver.horizon = times.back();
    if (c.solver.output_step <= 0.0 || c.solver.output_step > c.solver.horizon) {
        double spacing = times.back();
        for (std::size_t k = 1; k < times.size(); ++k) spacing = std::min(spacing, times[k] - times[k - 1]);
        c.solver.output_step = spacing;
    }
    const std::vector<CaseProblem> problems = check_case(c);
    if (!problems.empty()) throw InputError(problems.front().key + ": " + problems.front().message);
    SimulationOptions o;
    o.energy = false;
    const SimulationRun run = run_simulation(c, o);
    const TimeHistory& h = run.result.history;
    const std::vector<double>& v = column == "tip_velocity_m_s" ? h.tip_velocity : h.tip_v;
    if (h.t.empty()) throw std::runtime_error("the model wrote no time history");
    std::vector<double> out(times.size());
    for (std::size_t k = 0; k < times.size(); ++k) out[k] = interpolate(h.t, v, times[k]);
    return out;
}

FitResult fit_trajectory(const Case& base, const std::vector<FitParameter>& params, const MeasuredTrajectory& data,
                         const FitOptions& o) {
    const int n = static_cast<int>(params.size());
    const int samples = static_cast<int>(data.t.size());
    if (n == 0 || samples <= n) throw std::invalid_argument("fit_trajectory: need parameters and more samples than them");
    if (data.t.front() < 0.0) throw InputError(data.file + ": t_s: the record must start at t >= 0 (the model's t = 0)");

    std::vector<double> z(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) z[static_cast<std::size_t>(i)] = params[static_cast<std::size_t>(i)].start / scale_of(params[static_cast<std::size_t>(i)]);
    // The start must run: a case that cannot is the user's to fix, not Ceres' to step around.
    (void)model_trajectory(base, params, [&] {
        std::vector<double> x;
        for (const FitParameter& p : params) x.push_back(p.start);
        return x;
    }(), data.t, data.column);

    auto* residual = new Residual(base, params, data);
    auto* cost = new ceres::DynamicNumericDiffCostFunction<Residual, ceres::CENTRAL>(residual, ceres::TAKE_OWNERSHIP);
    cost->AddParameterBlock(n);
    cost->SetNumResiduals(samples);
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, z.data());
    for (int i = 0; i < n; ++i) {
        const FitParameter& p = params[static_cast<std::size_t>(i)];
        if (p.low) problem.SetParameterLowerBound(z.data(), i, *p.low / scale_of(p));
        if (p.high) problem.SetParameterUpperBound(z.data(), i, *p.high / scale_of(p));
    }
    StopCallback stop(*residual);
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_QR;
    so.max_num_iterations = o.max_iterations;
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
    ceres::Solve(so, &problem, &summary);
    if (residual->stopped() || stop_flag().load()) throw StopRequested(stop_signal());

    FitResult r;
    r.iterations = static_cast<int>(summary.iterations.size());
    r.converged = summary.termination_type == ceres::CONVERGENCE;
    r.message = summary.message;
    // The Jacobian and residuals at the solution, in the scaled parameters.
    double cost_value = 0.0;
    std::vector<double> res;
    ceres::CRSMatrix crs;
    problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost_value, &res, nullptr, &crs);
    r.simulations = residual->calls();
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(samples, n);
    for (int row = 0; row < crs.num_rows; ++row) {
        for (int k = crs.rows[static_cast<std::size_t>(row)]; k < crs.rows[static_cast<std::size_t>(row) + 1]; ++k) {
            J(row, crs.cols[static_cast<std::size_t>(k)]) = crs.values[static_cast<std::size_t>(k)];
        }
    }
    for (int i = 0; i < n; ++i) r.estimate.push_back(z[static_cast<std::size_t>(i)] * scale_of(params[static_cast<std::size_t>(i)]));
    r.model = model_trajectory(base, params, r.estimate, data.t, data.column);
    double ssr = 0.0, ssr_scaled = 0.0;
    for (int k = 0; k < samples; ++k) {
        const double d = r.model[static_cast<std::size_t>(k)] - data.value[static_cast<std::size_t>(k)];
        r.residual.push_back(d);
        ssr += d * d;
        ssr_scaled += res[static_cast<std::size_t>(k)] * res[static_cast<std::size_t>(k)];
    }
    r.rms = std::sqrt(ssr / samples);
    // Without a per-sample sigma the noise is estimated from the residuals (N - p degrees of freedom).
    r.sigma_from_residuals = data.sigma.empty();
    // The covariance s2 (J^T J)^-1 does not depend on how the residuals were scaled.
    const double s2 = r.sigma_from_residuals ? ssr_scaled / (samples - n) : 1.0;
    r.sigma = r.sigma_from_residuals ? std::sqrt(ssr / (samples - n)) : 0.0;

    // Undetermined parameters: the directions of J (in parameters scaled to their range or start)
    // whose singular value is below 1e-3 of the largest, and the parameters that take part in them.
    // Not roundoff: the Jacobian comes from central differences of simulations whose trajectories
    // carry a relative noise near 1e-10 (the modes are recomputed for every stiffness), so an exact
    // trade-off (E and nu through E / (1 - nu^2)) shows up near 1e-4 (measured), never at 1e-16;
    // the determined ones of the tests lie above 2e-2.
    r.undetermined.assign(static_cast<std::size_t>(n), "");
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
    const Eigen::VectorXd sv = svd.singularValues();
    const double top = sv.size() > 0 ? sv[0] : 0.0;
    for (int j = 0; j < sv.size(); ++j) {
        if (sv[j] > 1e-3 * top && top > 0.0) continue;
        for (int i = 0; i < n; ++i) {
            if (std::abs(svd.matrixV()(i, j)) < 0.1) continue;
            std::string why = J.col(i).norm() <= 1e-12 * std::max(top, 1e-300) ? "the data do not depend on it"
                                                                                  : "it trades off with";
            if (why != "the data do not depend on it") {
                for (int k = 0; k < n; ++k) {
                    if (k != i && std::abs(svd.matrixV()(k, j)) >= 0.1) why.append(" ").append(params[static_cast<std::size_t>(k)].path.text());
                }
            }
            r.undetermined[static_cast<std::size_t>(i)] = why;
        }
    }
    std::vector<int> kept;
    for (int i = 0; i < n; ++i) {
        if (r.undetermined[static_cast<std::size_t>(i)].empty()) kept.push_back(i);
    }
    const int m = static_cast<int>(kept.size());
    Eigen::MatrixXd Jk(samples, m);
    for (int a = 0; a < m; ++a) Jk.col(a) = J.col(kept[static_cast<std::size_t>(a)]);
    const Eigen::MatrixXd cov = s2 * (Jk.transpose() * Jk).ldlt().solve(Eigen::MatrixXd::Identity(m, m));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.std_error.assign(static_cast<std::size_t>(n), nan);
    r.correlation = Eigen::MatrixXd::Constant(n, n, nan);
    for (int a = 0; a < m; ++a) {
        const int i = kept[static_cast<std::size_t>(a)];
        r.std_error[static_cast<std::size_t>(i)] = std::sqrt(cov(a, a)) * scale_of(params[static_cast<std::size_t>(i)]);
        for (int b = 0; b < m; ++b) {
            r.correlation(i, kept[static_cast<std::size_t>(b)]) = cov(a, b) / std::sqrt(cov(a, a) * cov(b, b));
        }
    }
    for (int i = 0; i < n; ++i) {
        const std::size_t u = static_cast<std::size_t>(i);
        r.ci_low.push_back(r.estimate[u] - 1.96 * r.std_error[u]);
        r.ci_high.push_back(r.estimate[u] + 1.96 * r.std_error[u]);
    }
    return r;
}

}  // namespace vi
