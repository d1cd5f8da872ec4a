#include "calibration/fit_parameter.hpp"

#include <cmath>

#include "io/number_text.hpp"
#include "io/range_spec.hpp"
#include "io/units.hpp"
#include "model/input_error.hpp"

namespace vi {

std::string FitParameter::name() const {
    switch (kind) {
        case Kind::time_shift: return "time_shift_s";
        case Kind::scale: return "scale";
        case Kind::case_value: break;
    }
    return path.text();
}

FitParameter parse_fit_parameter(const std::string& text, const Case& c) {
    const auto fail = [&](const std::string& reason) { return InputError("--fit", text, reason); };
    const std::size_t eq = text.find('=');
    FitParameter p;
    p.setting = text;
    p.path = resolve_setting_path("--fit", text, c);
    if (is_integer_path(p.path)) throw fail(p.path.text() + " takes whole numbers, which a least-squares fit cannot vary");
    p.start = get_case_value(c, p.path);
    if (eq != std::string::npos) {
        const auto bounds = parse_bounds(text.substr(eq + 1), case_path_dimension(p.path));
        if (!bounds) throw fail("expected PATH or PATH=LOW:HIGH, two finite numbers (SI, or with units as in case files)");
        if (!(bounds->first < bounds->second)) throw fail("LOW must be below HIGH");
        p.low = bounds->first;
        p.high = bounds->second;
        if (p.start < *p.low || p.start > *p.high) {
            throw fail("the case's value " + round_trip_text(p.start) + " (the start) lies outside the bounds");
        }
    } else if (p.start == 0.0) {
        throw fail("the case's value is 0: give bounds PATH=LOW:HIGH so the fit has a scale to step by");
    }
    return p;
}

namespace {

// "LOW:HIGH" around a start of `start`, for the nuisance options.
void set_range(FitParameter& p, const std::string& option, const std::string& range, std::optional<Dimension> unit) {
    const auto fail = [&](const std::string& reason) { return InputError(option + " " + range + ": " + reason); };
    std::optional<std::pair<double, double>> bounds;
    try {
        bounds = parse_bounds(range, unit);
    } catch (const std::exception& e) {
        throw fail(e.what());
    }
    if (!bounds) throw fail("expected LOW:HIGH, two finite numbers");
    if (!(bounds->first < bounds->second)) throw fail("LOW must be below HIGH");
    if (p.start < bounds->first || p.start > bounds->second) {
        throw fail("the start " + round_trip_text(p.start) + " lies outside the range");
    }
    p.low = bounds->first;
    p.high = bounds->second;
}

}  // namespace

FitParameter time_shift_parameter(double duration, const std::string& range) {
    FitParameter p;
    p.kind = FitParameter::Kind::time_shift;
    p.setting = "--time-shift";
    p.start = 0.0;
    if (range.empty()) {
        p.low = -0.1 * duration;
        p.high = 0.1 * duration;
    } else {
        set_range(p, "--time-shift-range", range, Dimension::time);
    }
    return p;
}

FitParameter scale_parameter(const std::string& range) {
    FitParameter p;
    p.kind = FitParameter::Kind::scale;
    p.setting = "--scale";
    p.start = 1.0;
    if (range.empty()) {
        p.low = 0.5;
        p.high = 2.0;
    } else {
        set_range(p, "--scale-range", range, std::nullopt);
    }
    if (!(*p.low > 0.0)) throw InputError("--scale-range " + range + ": the scale must stay positive (LOW > 0)");
    return p;
}

void check_distinct(const std::vector<FitParameter>& params) {
    for (std::size_t i = 0; i < params.size(); ++i) {
        for (std::size_t k = 0; k < i; ++k) {
            if (params[k].kind == params[i].kind && params[k].path == params[i].path) {
                throw InputError(params[i].setting.rfind("--", 0) == 0 ? params[i].setting + ": given twice"
                                 : "--fit " + params[i].setting + ": " + params[i].name() + " is fitted twice");
            }
        }
    }
}

}  // namespace vi
