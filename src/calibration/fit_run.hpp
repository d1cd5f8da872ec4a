#pragma once
// A whole fit as `vibroimpact fit` runs it (docs/calibration.md): the fitted values from the
// --fit settings, the measured data read from its file, one stage or two, and what it reports
// (fit.json, fit_residuals.csv, the text summary).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "calibration/least_squares.hpp"
#include "io/measured_features.hpp"
#include "io/measured_trajectory.hpp"
#include "model/case.hpp"

namespace vi {

// What to fit and to which data: a trajectory (data) or features (features), not both.
struct FitRequest {
    std::vector<std::string> fit;    // --fit settings: "PATH" or "PATH=LOW:HIGH"
    std::string data;                // CSV trajectory file
    std::string features;            // CSV features file
    std::string column;              // the trajectory's measured column; "" for the watched point's <name>_m
    bool time_shift = false;         // fit the record's time offset t0 [s]
    std::string time_shift_range;    // its "LOW:HIGH" ("" for +-10 % of the record)
    bool scale = false;              // fit the measurement's gain
    std::string scale_range;         // its "LOW:HIGH" ("" for 0.5:2)
    bool two_stage = false;          // non-contact values before the first impact, then contact values
};

// A fit's outcome and reports. The data and the result the figures show are kept for them.
struct FitRun {
    nlohmann::json json;             // fit.json, less "command"
    std::string text;                // the summary the command prints, ending in a newline
    std::string residuals_csv;       // fit_residuals.csv
    std::vector<FitResult> results;  // the fit, or stage 1 and stage 2
    std::optional<MeasuredTrajectory> trajectory;  // the data of a trajectory fit
    std::optional<MeasuredFeatures> features;      // the data of a feature fit
    [[nodiscard]] const FitResult& shown() const { return results.back(); }  // the one the residuals are of
    [[nodiscard]] bool converged() const;
};

// Checks the request alone: one of data and features, the ranges only with their parameters, a
// column only for a trajectory. Throws InputError naming the option ("--column: ...").
void check_fit_request(const FitRequest& request);

// Checks the request and the --fit settings against c (InputError("--fit TEXT: reason")).
std::vector<FitParameter> fit_parameters(const Case& c, const FitRequest& request);

// Runs the fit of c (its file name `case_label` in the text) with o (threads, starts, progress).
// Throws InputError for bad input (a case key's error placed in the case file), StopRequested on a
// stop, std::runtime_error on numerical trouble; a fit that does not converge is a result.
FitRun run_fit(const Case& c, const std::string& case_label, const FitRequest& request, const FitOptions& o);

}  // namespace vi
