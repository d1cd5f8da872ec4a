#include "calibration/trajectory_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynamics/transient_start.hpp"
#include "impacts/simulation.hpp"
#include "model/case_checks.hpp"
#include "io/text_file.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"

namespace vi {
namespace {

// (t, y, dy/dt) at x: cubic Hermite between the samples around x (t ascending), the end values outside.
double hermite(const std::vector<double>& t, const std::vector<double>& y, const std::vector<double>* dy, double x) {
    const auto it = std::lower_bound(t.begin(), t.end(), x);
    if (it == t.begin()) return y.front();
    if (it == t.end()) return y.back();
    const std::size_t k = static_cast<std::size_t>(it - t.begin());
    const double h = t[k] - t[k - 1];
    const double s = (x - t[k - 1]) / h;
    if (!dy) return y[k - 1] + s * (y[k] - y[k - 1]);
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * y[k - 1] + (s3 - 2 * s2 + s) * h * (*dy)[k - 1] + (-2 * s3 + 3 * s2) * y[k] +
           (s3 - s2) * h * (*dy)[k];
}

bool is_velocity(const std::string& column) { return column.ends_with("_velocity_m_s"); }

// The nuisance values at x: the fitted ones from x, the others from `fixed`.
TrajectoryFixed nuisance_at(const std::vector<FitParameter>& params, const std::vector<double>& x,
                                const TrajectoryFixed& fixed) {
    TrajectoryFixed n = fixed;
    for (std::size_t i = 0; i < params.size(); ++i) {
        if (params[i].kind == FitParameter::Kind::time_shift) n.time_shift = x[i];
        if (params[i].kind == FitParameter::Kind::scale) n.scale = x[i];
    }
    return n;
}

// The earliest time shift the fit may try: the horizon must reach the last time minus it.
double lowest_shift(const std::vector<FitParameter>& params, const TrajectoryFixed& fixed, double now) {
    double low = std::min(0.0, std::min(fixed.time_shift, now));
    for (const FitParameter& p : params) {
        if (p.kind == FitParameter::Kind::time_shift && p.low) low = std::min(low, *p.low);
    }
    return low;
}

// What a residual is divided by without a sigma column: max |data| (Ceres' tolerances are absolute,
// and a record in metres, 1e-6, would look converged at the start).
double residual_unit(const MeasuredTrajectory& data) {
    double unit = 0.0;
    for (double v : data.value) unit = std::max(unit, std::abs(v));
    return unit > 0.0 ? unit : 1.0;
}

// The least-squares problem of a trajectory: residual (model - data) / sigma_k, or / max |data|
// without a sigma column.
LeastSquaresProblem trajectory_problem(const Case& base, const std::vector<FitParameter>& params,
                                       const MeasuredTrajectory& data, const TrajectoryFixed& fixed) {
    const double unit = residual_unit(data);
    LeastSquaresProblem p;
    p.params = params;
    p.residuals = static_cast<int>(data.t.size());
    p.sigma_known = !data.sigma.empty();
    p.evaluate = [&base, params, &data, fixed, unit](const std::vector<double>& x, double* r) {
        const std::vector<double> m = model_trajectory(base, params, x, data.t, data.column, fixed);
        for (std::size_t k = 0; k < m.size(); ++k) r[k] = (m[k] - data.value[k]) / (data.sigma.empty() ? unit : data.sigma[k]);
    };
    return p;
}

// "FILE:LINE" of a sample (the file alone when the lines are not known: data made in code).
std::string sample_place(const MeasuredTrajectory& data, std::size_t k) {
    return k < data.line.size() ? data.file + ":" + std::to_string(data.line[k]) : data.file;
}

// The trajectory model sets two solver settings itself: the horizon always (the last data time less
// the lowest allowed time shift) and the output step when the case gives none that fits (the data's
// smallest spacing). A case check that refuses one of them is about the data, not about a line of
// the case file: the message names the data file, the sample that sets it and the value derived.
InputError blame_derived_setting(const InputError& e, const Case& base, const std::vector<FitParameter>& params,
                                 const MeasuredTrajectory& data, const TrajectoryFixed& fixed) {
    const std::string what = e.what();
    const double low = lowest_shift(params, fixed, fixed.time_shift);
    const double horizon = std::max(fixed.min_horizon, data.t.back() - low);
    const bool step_derived = base.solver.output_step <= 0.0 || base.solver.output_step > horizon;
    const std::string shifted = low < 0.0 ? " less the lowest allowed time shift, " + significant(low, 6) + " s" : "";
    if (what.rfind("solver.horizon: ", 0) == 0) {
        return InputError(one_line(sample_place(data, data.t.size() - 1) + ": t_s: the record's last time, " +
                                   significant(data.t.back(), 6) + " s" + shifted + ", makes the model's horizon " +
                                   significant(horizon, 6) + " s: " + what.substr(16)));
    }
    if (what.rfind("solver.output_step: ", 0) == 0 && step_derived) {
        std::size_t at = 1;
        for (std::size_t k = 2; k < data.t.size(); ++k) {
            if (data.t[k] - data.t[k - 1] < data.t[at] - data.t[at - 1]) at = k;
        }
        const double spacing = data.t.size() > 1 ? data.t[at] - data.t[at - 1] : horizon;
        return InputError(one_line(sample_place(data, std::min(at, data.t.size() - 1)) +
                                   ": t_s: the samples' smallest spacing, " + significant(spacing, 6) +
                                   " s, is the model's output step (the case gives none): " + what.substr(20)));
    }
    return e;
}

// The start must run and its misfit must be a number: a case that cannot run is the user's to fix,
// not Ceres' to step around, and data whose (model - data) / sigma squares past double's range
// (a sigma in the wrong unit) would reach Ceres as an infinite cost.
void check_start(const Case& base, const std::vector<FitParameter>& params, const MeasuredTrajectory& data,
                 const TrajectoryFixed& fixed) {
    std::vector<double> x0;
    for (const FitParameter& p : params) x0.push_back(p.start);
    std::vector<double> m0;
    try {
        m0 = model_trajectory(base, params, x0, data.t, data.column, fixed);
    } catch (const InputError& e) {
        throw blame_derived_setting(e, base, params, data, fixed);
    }
    const double unit = residual_unit(data);
    std::vector<double> w(m0.size());
    for (std::size_t k = 0; k < m0.size(); ++k) w[k] = (m0[k] - data.value[k]) / (data.sigma.empty() ? unit : data.sigma[k]);
    const std::size_t k = overflowing_residual(w);
    if (k == w.size()) return;
    const std::string over = data.sigma.empty() ? "max |" + data.column + "|" : "sigma";
    throw InputError(one_line(sample_place(data, k) + ": " + (data.sigma.empty() ? data.column : std::string("sigma")) +
                              ": (model - data) / " + over + " = " + significant(w[k], 3) +
                              " at the start values: the misfit's sum of squares is not a finite number in double "
                              "precision; check the units of " + data.column + " and sigma"));
}

}  // namespace

std::string watched_point_name(const Case& c) { return watched_point_of(c).name; }

void check_trajectory_column(const Case& c, const std::string& column) {
    const std::string name = watched_point_name(c);
    if (column == name + "_m" || column == name + "_velocity_m_s") return;
    const std::string what = name == "tip" ? "the free end (tip)" : name == "midspan" ? "the mid-span (a beam held at both ends)"
                                                                                       : "initial.position (point)";
    throw InputError("--column " + column + ": this case's watched point is " + what + ": its columns are " + name +
                     "_m and " + name + "_velocity_m_s");
}

std::vector<double> model_trajectory(const Case& base, const std::vector<FitParameter>& params,
                                     const std::vector<double>& x, const std::vector<double>& times,
                                     const std::string& column, const TrajectoryFixed& fixed) {
    Case c = base;
    for (std::size_t i = 0; i < params.size(); ++i) {
        if (!params[i].nuisance()) set_case_value(c, params[i].path, x[i]);
    }
    const TrajectoryFixed n = nuisance_at(params, x, fixed);
    // A horizon that does not move during the fit: the same work for every trial design.
    c.solver.horizon = std::max(fixed.min_horizon, times.back() - lowest_shift(params, fixed, n.time_shift));
    if (c.solver.output_step <= 0.0 || c.solver.output_step > c.solver.horizon) {
        double spacing = times.back() - times.front();
        for (std::size_t k = 1; k < times.size(); ++k) spacing = std::min(spacing, times[k] - times[k - 1]);
        c.solver.output_step = std::min(spacing, c.solver.horizon);
    }
    const std::vector<CaseProblem> problems = check_case(c);
    if (!problems.empty()) throw InputError(problems.front().key + ": " + problems.front().message);
    SimulationOptions o;
    o.energy = false;
    const SimulationRun run = run_simulation(c, o);
    const TimeHistory& h = run.result.history;
    if (h.t.empty()) throw std::runtime_error("the model wrote no time history");
    const bool velocity = is_velocity(column);
    const std::vector<double>& v = velocity ? h.tip_velocity : h.tip_v;
    std::vector<double> out(times.size());
    for (std::size_t k = 0; k < times.size(); ++k) {
        out[k] = n.scale * hermite(h.t, v, velocity ? nullptr : &h.tip_velocity, times[k] - n.time_shift);
    }
    return out;
}

FitResult fit_trajectory(const Case& base, const std::vector<FitParameter>& params, const MeasuredTrajectory& data,
                         const FitOptions& o, const TrajectoryFixed& fixed) {
    const int n = static_cast<int>(params.size());
    const int samples = static_cast<int>(data.t.size());
    if (n == 0 || samples <= n) throw std::invalid_argument("fit_trajectory: need parameters and more samples than them");
    const bool shifted = std::any_of(params.begin(), params.end(),
                                     [](const FitParameter& p) { return p.kind == FitParameter::Kind::time_shift; });
    if (!shifted && fixed.time_shift == 0.0 && data.t.front() < 0.0) {
        throw InputError(data.file + ": t_s: the record must start at t >= 0 (the model's t = 0), or fit --time-shift");
    }
    check_start(base, params, data, fixed);

    const LeastSquaresProblem p = trajectory_problem(base, params, data, fixed);
    FitResult r = fit_least_squares(p, o);
    r.model = model_trajectory(base, params, r.estimate, data.t, data.column, fixed);
    double ssr = 0.0;
    for (int k = 0; k < samples; ++k) {
        const double d = r.model[static_cast<std::size_t>(k)] - data.value[static_cast<std::size_t>(k)];
        r.residual.push_back(d);
        ssr += d * d;
    }
    r.rms = std::sqrt(ssr / samples);
    r.sigma = r.sigma_from_residuals ? std::sqrt(ssr / (samples - n)) : 0.0;
    return r;
}

TwoStageFit fit_two_stage(const Case& base, const std::vector<FitParameter>& params, const MeasuredTrajectory& data,
                          const FitOptions& o) {
    TwoStageFit f;
    std::vector<FitParameter> p1, p2;
    for (std::size_t i = 0; i < params.size(); ++i) {
        (params[i].contact() ? f.stage2_params : f.stage1_params).push_back(i);
        (params[i].contact() ? p2 : p1).push_back(params[i]);
    }
    if (p1.empty()) {
        throw InputError("--two-stage: stage 1 (the record before the first impact) has no parameter: every fitted value is "
                         "a contact parameter (supports[...]); fit a beam or damping value too, or fit in one stage");
    }
    if (p2.empty()) {
        throw InputError("--two-stage: stage 2 (the impacts) has no parameter: no fitted value is a contact parameter "
                         "(supports[...]); fit in one stage");
    }
    // The first impact of the model at the start values, in data time.
    Case start = base;
    TrajectoryFixed at_start;
    for (const FitParameter& p : params) {
        if (!p.nuisance()) set_case_value(start, p.path, p.start);
        if (p.kind == FitParameter::Kind::time_shift) at_start.time_shift = p.start;
        if (p.kind == FitParameter::Kind::scale) at_start.scale = p.start;
    }
    start.solver.horizon = data.t.back() - std::min(0.0, at_start.time_shift);
    SimulationOptions so;
    so.history = false;
    so.energy = false;
    SimulationRun run;
    try {
        run = run_simulation(start, so);
    } catch (const InputError& e) {
        throw blame_derived_setting(e, base, params, data, at_start);
    }
    if (run.result.episodes.empty()) {
        throw InputError("--two-stage: the model at the start values has no impact within the record; fit in one stage");
    }
    f.split_time = run.result.episodes.front().t_on + at_start.time_shift;
    MeasuredTrajectory before = data;
    before.t.clear();
    before.value.clear();
    before.sigma.clear();
    for (std::size_t k = 0; k < data.t.size() && data.t[k] < f.split_time; ++k) {
        before.t.push_back(data.t[k]);
        before.value.push_back(data.value[k]);
        if (!data.sigma.empty()) before.sigma.push_back(data.sigma[k]);
    }
    f.split_samples = before.t.size();
    if (before.t.size() <= p1.size()) {
        throw InputError("--two-stage: " + std::to_string(before.t.size()) + " samples lie before the first impact (t = " +
                         std::to_string(f.split_time * 1e6) + " us at the start values), not more than stage 1's " +
                         std::to_string(p1.size()) + " parameters");
    }
    TrajectoryFixed stage1_fixed = at_start;
    stage1_fixed.min_horizon = data.t.back() - lowest_shift(params, at_start, at_start.time_shift);
    f.stage1 = fit_trajectory(start, p1, before, o, stage1_fixed);
    // Stage 2: stage 1's values fixed.
    Case fixed_case = start;
    TrajectoryFixed fixed = at_start;
    for (std::size_t a = 0; a < p1.size(); ++a) {
        const double v = f.stage1.estimate[a];
        if (!p1[a].nuisance()) set_case_value(fixed_case, p1[a].path, v);
        if (p1[a].kind == FitParameter::Kind::time_shift) fixed.time_shift = v;
        if (p1[a].kind == FitParameter::Kind::scale) fixed.scale = v;
    }
    f.stage2 = fit_trajectory(fixed_case, p2, data, o, fixed);
    f.estimate.assign(params.size(), 0.0);
    for (std::size_t a = 0; a < p1.size(); ++a) f.estimate[f.stage1_params[a]] = f.stage1.estimate[a];
    for (std::size_t a = 0; a < p2.size(); ++a) f.estimate[f.stage2_params[a]] = f.stage2.estimate[a];

    // Stage 2 held stage 1's values fixed, so its own intervals miss their uncertainty: to first
    // order the stage 2 estimate moves by G d1 when stage 1's moves by d1, G = -(J2^T J2)^-1 J2^T J1
    // (J1, J2: the whole record's residuals against each stage's parameters), and its covariance
    // is V2 + G V1 G^T. An undetermined stage 1 parameter carries none (its variance is unknown).
    f.stage2_conditional_std_error = f.stage2.std_error;
    const LeastSquaresProblem whole = trajectory_problem(start, params, data, at_start);
    const Eigen::MatrixXd J = jacobian_at(whole, f.estimate, f.stage2.simulations);
    Eigen::MatrixXd J1(J.rows(), static_cast<Eigen::Index>(p1.size())), J2(J.rows(), static_cast<Eigen::Index>(p2.size()));
    for (std::size_t a = 0; a < p1.size(); ++a) J1.col(static_cast<Eigen::Index>(a)) = J.col(static_cast<Eigen::Index>(f.stage1_params[a]));
    for (std::size_t a = 0; a < p2.size(); ++a) J2.col(static_cast<Eigen::Index>(a)) = J.col(static_cast<Eigen::Index>(f.stage2_params[a]));
    const Eigen::MatrixXd G = -(J2.transpose() * J2).ldlt().solve(J2.transpose() * J1);
    Eigen::MatrixXd V1 = covariance(f.stage1);
    for (Eigen::Index a = 0; a < V1.rows(); ++a) {
        for (Eigen::Index b = 0; b < V1.cols(); ++b) {
            if (!std::isfinite(V1(a, b))) V1(a, b) = 0.0;
        }
    }
    set_covariance(f.stage2, covariance(f.stage2) + G * V1 * G.transpose());
    return f;
}

}  // namespace vi
