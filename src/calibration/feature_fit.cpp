#include "calibration/feature_fit.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <variant>

#include "dynamics/transient_start.hpp"
#include "statics/pullin.hpp"
#include "fem/rayleigh.hpp"
#include "impacts/simulation.hpp"
#include "model/case_checks.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"
#include "sweep/case_paths.hpp"
#include "sweep/columns.hpp"

namespace vi {
namespace {

// V_PI_V and the numeric columns of a pullin sweep come from the static pull-in trace.
bool from_pullin(const std::string& name) {
    if (name == "V_PI_V") return true;
    for (const SweepColumn& c : sweep_result_columns(SweepAnalysis::pullin, 0)) {
        if (c.name == name) return true;
    }
    return false;
}

bool from_transient(const std::string& name) {
    return name != "f1_hz" && name != "q1" && !from_pullin(name);
}

// The pull-in trace's value of a feature, or FeatureMissing saying why it has none.
double pullin_feature(const std::string& name, const PullinResult& r) {
    if (name == "V_PI_V") {
        if (!r.pullin) throw FeatureMissing("V_PI_V: the design has no pull-in before its branch ends (" + r.end + ")");
        return r.pullin->voltage;
    }
    const std::vector<SweepColumn> columns = sweep_result_columns(SweepAnalysis::pullin, 0);
    const std::vector<SweepCell> cells = pullin_cells(r);
    for (std::size_t k = 0; k < columns.size(); ++k) {
        if (columns[k].name != name) continue;
        if (const std::optional<double> v = numeric_cell(cells[k])) return *v;
    }
    throw FeatureMissing(name + ": the design's pull-in trace has no such point (" + r.end + ")");
}

// f1 [Hz] and Q1 of a built model.
double modal_feature(const std::string& name, const BeamModel& b) {
    if (name == "f1_hz") return b.omega1 / (2.0 * std::numbers::pi);
    const double zeta = rayleigh_ratio(b.rayleigh, b.omega1);
    if (!(zeta > 0.0)) throw FeatureMissing("q1: the design's first mode is undamped (zeta_1 = 0: Q infinite)");
    return 1.0 / (2.0 * zeta);
}

// Why a sweep column is empty, for the feature's message.
std::string why_missing(const std::string& name) {
    if (name == "T_s" || name == "T1_s") return "fewer than two impacts within the horizon";
    if (name == "T2_s" || name == "impact1_peak_force_n") return "no impact within the horizon, or the first still closed at its end";
    if (name == "Tp_s") return "the horizon ends before the transient settles";
    if (name == "closing_time_s") return "the switch does not close within the horizon";
    return "no impact within the horizon";
}

}  // namespace

void check_features(const Case& c, const MeasuredFeatures& data) {
    for (const MeasuredFeature& f : data.features) {
        if ((from_pullin(f.name) || f.name == "closing_time_s") && c.electrodes.empty()) {
            throw InputError(data.file + ":" + std::to_string(f.line) + ": " + f.name +
                             ": the case has no electrode (the feature needs an actuated switch)");
        }
    }
}

std::vector<double> model_features(const Case& base, const std::vector<FitParameter>& params,
                                   const std::vector<double>& x, const MeasuredFeatures& data) {
    Case c = base;
    for (std::size_t i = 0; i < params.size(); ++i) set_case_value(c, params[i].path, x[i]);
    const std::vector<CaseProblem> problems = check_case(c);
    if (!problems.empty()) throw InputError(problems.front().key + ": " + problems.front().message);
    bool transient = false, modal = false, pullin = false;
    for (const MeasuredFeature& f : data.features) {
        transient = transient || from_transient(f.name);
        modal = modal || f.name == "f1_hz" || f.name == "q1";
        pullin = pullin || from_pullin(f.name);
    }
    std::optional<SimulationRun> run;
    std::optional<BeamModel> built;
    std::vector<SweepCell> cells;
    std::vector<SweepColumn> columns;
    if (transient) {
        // A sweep point's run: the summary only.
        SimulationOptions o;
        o.history = false;
        o.energy = false;
        run = run_simulation(c, o);
        cells = simulate_cells(*run);
        columns = sweep_result_columns(SweepAnalysis::simulate, 0);
    } else if (modal) {
        built = build_beam_model(c);
    }
    std::optional<PullinResult> trace;
    if (pullin) {
        PullinOptions po;
        po.frequency_points = 0;  // the voltages and travels only
        trace = trace_pullin(c, po);
    }
    std::vector<double> out;
    for (const MeasuredFeature& f : data.features) {
        if (from_pullin(f.name)) {
            out.push_back(pullin_feature(f.name, *trace));
        } else if (!from_transient(f.name)) {
            out.push_back(modal_feature(f.name, run ? run->built.model : *built));
        } else {
            std::optional<double> v;
            for (std::size_t k = 0; k < columns.size(); ++k) {
                if (columns[k].name == f.name) v = numeric_cell(cells[k]);
            }
            if (!v) throw FeatureMissing(f.name + ": the model gives none at this design (" + why_missing(f.name) + ")");
            out.push_back(*v);
        }
    }
    return out;
}

FitResult fit_features(const Case& base, const std::vector<FitParameter>& params, const MeasuredFeatures& data,
                       const FitOptions& o) {
    check_features(base, data);
    for (const FitParameter& p : params) {
        if (p.nuisance()) throw InputError(p.setting + ": a nuisance parameter of a trajectory, not of features (--data)");
    }
    std::vector<double> x0;
    for (const FitParameter& p : params) x0.push_back(p.start);
    std::vector<double> m0;
    try {
        m0 = model_features(base, params, x0, data);
    } catch (const FeatureMissing& e) {
        const std::string what = e.what();
        std::size_t line = 0;
        for (const MeasuredFeature& f : data.features) {
            if (what.rfind(f.name + ":", 0) == 0) line = f.line;
        }
        throw InputError(data.file + ":" + std::to_string(line) + ": " + what + " (at the case's values, the start)");
    }
    // A misfit that squares past double's range (a sigma in the wrong unit) would reach Ceres as an
    // infinite cost: refused at the start, naming the feature.
    std::vector<double> w;
    for (std::size_t k = 0; k < m0.size(); ++k) w.push_back((m0[k] - data.features[k].value) / data.features[k].sigma);
    if (const std::size_t k = overflowing_residual(w); k < w.size()) {
        const MeasuredFeature& f = data.features[k];
        throw InputError(data.file + ":" + std::to_string(f.line) + ": " + f.name + ": (model - value) / sigma = " +
                         significant(w[k], 3) + " at the start values: the misfit's sum of squares is not a finite "
                         "number in double precision; check the value's unit and its sigma");
    }
    LeastSquaresProblem p;
    p.params = params;
    p.residuals = static_cast<int>(data.features.size());
    p.sigma_known = true;
    p.evaluate = [&](const std::vector<double>& x, double* r) {
        const std::vector<double> m = model_features(base, params, x, data);
        for (std::size_t k = 0; k < m.size(); ++k) r[k] = (m[k] - data.features[k].value) / data.features[k].sigma;
    };
    FitResult r = fit_least_squares(p, o);
    r.model = model_features(base, params, r.estimate, data);
    double chi2 = 0.0;
    for (std::size_t k = 0; k < r.model.size(); ++k) {
        r.residual.push_back(r.model[k] - data.features[k].value);
        chi2 += std::pow(r.residual.back() / data.features[k].sigma, 2);
    }
    // The features have different units: the rms is of the residuals in units of their sigma.
    r.rms = std::sqrt(chi2 / static_cast<double>(r.model.size()));
    r.sigma = 0.0;
    return r;
}

}  // namespace vi
