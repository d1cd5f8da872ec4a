#pragma once
// The yield against a specification: the fraction of samples whose quantity meets "COLUMN<=VALUE"
// or "COLUMN>=VALUE", with its binomial confidence interval (Wilson's score interval; docs/uq.md).

#include <cstddef>
#include <string>
#include <vector>

#include "uq/statistics.hpp"

namespace vi {

struct YieldSpec {
    std::string text;    // as written: "pullin_voltage_v<=40"
    std::string column;  // the quantity's column
    bool upper = true;   // COLUMN <= bound (else COLUMN >= bound)
    double bound = 0.0;  // in the column's SI unit
    // A missing value (the sample has no such quantity, e.g. no closing) does not meet the spec.
    [[nodiscard]] bool met(double value) const { return upper ? value <= bound : value >= bound; }
};

// Parses "COLUMN<=VALUE" or "COLUMN>=VALUE" against the analysis's numeric columns. Throws
// InputError("--spec TEXT: reason") for another form, a VALUE that is not a finite number, or a
// COLUMN that is none of them (listing them).
YieldSpec parse_yield_spec(const std::string& text, const std::vector<std::string>& numeric_columns);

// Wilson's score interval for a binomial proportion, successes of n, at two-sided `confidence`
// (Wilson 1927; Brown, Cai and DasGupta 2001 recommend it over the Wald interval, which collapses at
// 0 and n). n > 0.
Interval wilson_interval(std::size_t successes, std::size_t n, double confidence);

// Samples needed for a Wilson half-width about `half_width` at yield p: z^2 p (1 - p) / h^2 (the
// normal approximation the interval tends to), at least 1.
std::size_t samples_for_yield(double p, double half_width, double confidence);

}  // namespace vi
