#include "uq/yield.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>

#include "io/range_spec.hpp"
#include "model/input_error.hpp"

namespace vi {
namespace {

double z_of(double confidence) {
    return boost::math::quantile(boost::math::normal(0.0, 1.0), 0.5 + 0.5 * confidence);
}

}  // namespace

YieldSpec parse_yield_spec(const std::string& text, const std::vector<std::string>& numeric_columns) {
    const auto fail = [&](const std::string& reason) { return InputError("--spec " + text + ": " + reason); };
    YieldSpec s;
    s.text = text;
    std::size_t at = text.find("<=");
    s.upper = at != std::string::npos;
    if (!s.upper) at = text.find(">=");
    if (at == std::string::npos) throw fail("expected COLUMN<=VALUE or COLUMN>=VALUE, e.g. pullin_voltage_v<=40");
    s.column = text.substr(0, at);
    const std::optional<double> v = finite_number(text.substr(at + 2));
    if (!v) throw fail("VALUE must be a finite number in the column's SI unit");
    s.bound = *v;
    for (const std::string& c : numeric_columns) {
        if (c == s.column) return s;
    }
    std::string names;
    for (const std::string& c : numeric_columns) names += (names.empty() ? "" : ", ") + c;
    throw fail("no numeric column '" + s.column + "' in this analysis (one of: " + names + ")");
}

Interval wilson_interval(std::size_t successes, std::size_t n, double confidence) {
    const double z = z_of(confidence);
    const double nn = static_cast<double>(n);
    const double p = static_cast<double>(successes) / nn;
    const double z2n = z * z / nn;
    const double centre = (p + 0.5 * z2n) / (1.0 + z2n);
    const double half = z * std::sqrt(p * (1.0 - p) / nn + 0.25 * z2n / nn) / (1.0 + z2n);
    return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::size_t samples_for_yield(double p, double half_width, double confidence) {
    const double z = z_of(confidence);
    return static_cast<std::size_t>(std::max(1.0, std::ceil(z * z * p * (1.0 - p) / (half_width * half_width))));
}

}  // namespace vi
