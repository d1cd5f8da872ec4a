#include "uq/distribution.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/number_text.hpp"
#include "io/range_spec.hpp"

namespace vi {
namespace {

const boost::math::normal kStandard(0.0, 1.0);

double phi(double z) { return boost::math::pdf(kStandard, z); }
double cdf(double z) { return boost::math::cdf(kStandard, z); }
double inverse_cdf(double u) { return boost::math::quantile(kStandard, u); }

std::vector<std::string> split(std::string_view text) {
    std::vector<std::string> parts;
    std::size_t at = 0;
    while (true) {
        const std::size_t colon = text.find(':', at);
        parts.emplace_back(text.substr(at, colon == std::string_view::npos ? std::string_view::npos : colon - at));
        if (colon == std::string_view::npos) return parts;
        at = colon + 1;
    }
}

// The truncated normal's bounds in units of its SD from its mean.
std::pair<double, double> standard_bounds(const Distribution& d) { return {(d.low - d.a) / d.b, (d.high - d.a) / d.b}; }

}  // namespace

double Distribution::quantile(double u) const {
    switch (kind) {
        case Kind::normal: return a + b * inverse_cdf(u);
        case Kind::uniform: return a + (b - a) * u;
        case Kind::lognormal: return a * std::exp(b * inverse_cdf(u));
        case Kind::truncnormal: {
            // The bounds hold the mean, so CDF(alpha) < 1/2 < CDF(beta): no cancellation in between.
            const auto [alpha, beta] = standard_bounds(*this);
            const double fa = cdf(alpha), fb = cdf(beta);
            return std::clamp(a + b * inverse_cdf(fa + u * (fb - fa)), low, high);
        }
    }
    return a;
}

double Distribution::mean() const {
    switch (kind) {
        case Kind::normal: return a;
        case Kind::uniform: return 0.5 * (a + b);
        case Kind::lognormal: return a * std::exp(0.5 * b * b);
        case Kind::truncnormal: {
            const auto [alpha, beta] = standard_bounds(*this);
            return a + b * (phi(alpha) - phi(beta)) / (cdf(beta) - cdf(alpha));
        }
    }
    return a;
}

double Distribution::std_dev() const {
    switch (kind) {
        case Kind::normal: return b;
        case Kind::uniform: return (b - a) / std::sqrt(12.0);
        case Kind::lognormal: return mean() * std::sqrt(std::expm1(b * b));
        case Kind::truncnormal: {
            const auto [alpha, beta] = standard_bounds(*this);
            const double z = cdf(beta) - cdf(alpha);
            const double r = (phi(alpha) - phi(beta)) / z;
            return b * std::sqrt(1.0 + (alpha * phi(alpha) - beta * phi(beta)) / z - r * r);
        }
    }
    return b;
}

const char* Distribution::name() const {
    switch (kind) {
        case Kind::normal: return "normal";
        case Kind::uniform: return "uniform";
        case Kind::lognormal: return "lognormal";
        case Kind::truncnormal: return "truncnormal";
    }
    return "normal";
}

Distribution parse_distribution(std::string_view text, std::optional<Dimension> unit_of) {
    const std::vector<std::string> p = split(text);
    const std::string& kind = p.front();
    const auto expect = [&](std::size_t values, const char* form) {
        if (p.size() != values + 1) {
            throw std::invalid_argument(kind + " takes " + std::to_string(values) + " values: " + form);
        }
    };
    const auto value = [&](std::size_t k, std::optional<Dimension> unit) { return parse_value(p.at(k), unit); };
    Distribution d;
    if (kind == "normal") {
        expect(2, "normal:MEAN:SD");
        d = {Distribution::Kind::normal, value(1, unit_of), value(2, unit_of), 0.0, 0.0};
    } else if (kind == "uniform") {
        expect(2, "uniform:LOW:HIGH");
        d = {Distribution::Kind::uniform, value(1, unit_of), value(2, unit_of), 0.0, 0.0};
        if (!(d.a < d.b)) throw std::invalid_argument("uniform: LOW must be below HIGH");
        return d;
    } else if (kind == "lognormal") {
        expect(2, "lognormal:MEDIAN:SIGMA_LOG (SIGMA_LOG a plain number, the SD of the value's logarithm)");
        d = {Distribution::Kind::lognormal, value(1, unit_of), value(2, std::nullopt), 0.0, 0.0};
        if (!(d.a > 0.0)) throw std::invalid_argument("lognormal: MEDIAN must be positive");
        if (!(d.b > 0.0)) throw std::invalid_argument("lognormal: SIGMA_LOG must be positive");
        return d;
    } else if (kind == "truncnormal") {
        expect(4, "truncnormal:MEAN:SD:LOW:HIGH");
        d = {Distribution::Kind::truncnormal, value(1, unit_of), value(2, unit_of), value(3, unit_of), value(4, unit_of)};
        if (!(d.low < d.high)) throw std::invalid_argument("truncnormal: LOW must be below HIGH");
        if (!(d.low < d.a && d.a < d.high)) {
            throw std::invalid_argument("truncnormal: the bounds " + p[3] + " .. " + p[4] + " must hold the mean " +
                                        p[1] + " between them");
        }
    } else {
        throw std::invalid_argument("unknown distribution '" + kind +
                                    "' (normal:MEAN:SD, uniform:LOW:HIGH, lognormal:MEDIAN:SIGMA_LOG, "
                                    "truncnormal:MEAN:SD:LOW:HIGH)");
    }
    if (!(d.b > 0.0)) throw std::invalid_argument(kind + ": SD must be positive (got " + round_trip_text(d.b) + ")");
    return d;
}

}  // namespace vi
