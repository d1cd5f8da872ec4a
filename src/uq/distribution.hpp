#pragma once
// The distribution of one case value across fabricated dies: normal, uniform, lognormal or
// truncated normal, read from "normal:MEAN:SD"-style text (docs/uq.md).

#include <optional>
#include <string>
#include <string_view>

#include "io/units.hpp"

namespace vi {

struct Distribution {
    enum class Kind { normal, uniform, lognormal, truncnormal };
    Kind kind = Kind::normal;
    // normal and truncnormal: a = mean, b = SD; truncnormal also low, high (the bounds). uniform:
    // a = low, b = high. lognormal: a = median, b = sigma of the log (dimensionless). In the value's
    // SI unit except sigma of the log.
    double a = 0.0, b = 0.0, low = 0.0, high = 0.0;

    // The value whose cumulative probability is u, 0 < u < 1 (the inverse CDF).
    [[nodiscard]] double quantile(double u) const;
    // Mean and standard deviation of the distribution (the truncated normal's, not its parent's).
    [[nodiscard]] double mean() const;
    [[nodiscard]] double std_dev() const;
    // "normal", "uniform", "lognormal", "truncnormal".
    [[nodiscard]] const char* name() const;
};

// Parses "normal:MEAN:SD", "uniform:LOW:HIGH", "lognormal:MEDIAN:SIGMA_LOG" or
// "truncnormal:MEAN:SD:LOW:HIGH"; values in SI or, when `unit_of` is given, with one of its units
// as in case files ("0.1um"); SIGMA_LOG is a plain number. Throws std::invalid_argument with a
// one-line reason: an unknown distribution, a wrong count of values, SD or SIGMA_LOG not positive,
// LOW not below HIGH, a median not positive, truncation bounds that do not hold the mean between them.
Distribution parse_distribution(std::string_view text, std::optional<Dimension> unit_of = std::nullopt);

}  // namespace vi
