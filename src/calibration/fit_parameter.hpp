#pragma once
// One value a fit estimates: a case value (a --fit PATH, as --set of sweep) or a nuisance parameter
// of the measurement (the record's time shift, its calibration scale), with its start and bounds.

#include <optional>
#include <string>
#include <vector>

#include "model/case.hpp"
#include "sweep/case_paths.hpp"

namespace vi {

struct FitParameter {
    enum class Kind { case_value, time_shift, scale };
    Kind kind = Kind::case_value;
    std::string setting;                // as given ("--fit" text, "--time-shift", "--scale")
    CasePath path;                      // the case value (Kind::case_value)
    double start = 0.0;                 // the case's value, 0 s or 1 [SI]
    std::optional<double> low, high;    // bounds [SI]

    // The name in reports: the path's text, "time_shift_s" or "scale".
    [[nodiscard]] std::string name() const;
    // Of the measurement, not of the device.
    [[nodiscard]] bool nuisance() const { return kind != Kind::case_value; }
    // A contact parameter: a value under supports[...].
    [[nodiscard]] bool contact() const { return kind == Kind::case_value && path.section == "supports"; }
    // The step scale: its bound range, else the size of its start.
    [[nodiscard]] double scale() const { return low && high ? *high - *low : std::abs(start); }
};

// Parses a --fit setting ("PATH" or "PATH=LOW:HIGH", SI or with units) against the case. Throws
// InputError("--fit TEXT: reason"): an unknown or whole-number path, bounds reversed or not numbers,
// a start outside the bounds, a start of 0 without bounds (no scale to step by).
FitParameter parse_fit_parameter(const std::string& text, const Case& c);

// The time shift t0 of a record (the model is read at t - t0) within `range` ("LOW:HIGH" in s or
// with a time unit), by default +-10 % of the record's duration `duration` [s]. Throws
// InputError("--time-shift-range TEXT: reason").
FitParameter time_shift_parameter(double duration, const std::string& range = "");

// The gain g of the measurement (data = g * model) within `range` ("LOW:HIGH", default 0.5:2).
// Throws InputError("--scale-range TEXT: reason").
FitParameter scale_parameter(const std::string& range = "");

// Throws InputError("--fit TEXT: PATH is fitted twice") when two parameters are the same.
void check_distinct(const std::vector<FitParameter>& params);

}  // namespace vi
