#include "io/range_spec.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace vi {
namespace {

std::vector<std::string> split(std::string_view s, char sep) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t pos = s.find(sep, start);
        parts.emplace_back(s.substr(start, pos == std::string_view::npos ? std::string_view::npos : pos - start));
        if (pos == std::string_view::npos) break;
        start = pos + 1;
    }
    return parts;
}

double number(const std::string& text, std::optional<Dimension> unit_of = std::nullopt) {
    const std::size_t b = text.find_first_not_of(" \t");
    const std::size_t e = text.find_last_not_of(" \t");
    if (b == std::string::npos) throw std::invalid_argument("empty value in range");
    const std::string t = text.substr(b, e - b + 1);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() + t.size()) {
        if (unit_of && *unit_of != Dimension::dimensionless && end != t.c_str()) {  // a number, then a unit
            try {
                return parse_quantity(t, *unit_of);
            } catch (const std::invalid_argument& err) {
                throw std::invalid_argument("'" + t + "': " + err.what());
            }
        }
        throw std::invalid_argument("'" + t + "' is not a number");
    }
    if (!std::isfinite(v)) throw std::invalid_argument("'" + t + "' is not a finite number");
    return v;
}

int count_of(const std::string& text) {
    const double c = number(text);
    if (c != std::floor(c) || c < 1 || c > 1e7) {
        throw std::invalid_argument("count '" + text + "' must be a whole number from 1 to 10000000");
    }
    return static_cast<int>(c);
}

std::vector<double> linear(double a, double b, int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(n == 1 ? a : a + (b - a) * i / (n - 1));
    if (n > 1) v.back() = b;
    return v;
}

}  // namespace

std::vector<double> parse_range_spec(std::string_view spec, std::optional<Dimension> unit_of) {
    if (spec.find_first_not_of(" \t") == std::string_view::npos) throw std::invalid_argument("empty range");
    if (spec.substr(0, 4) == "log:") {
        const auto p = split(spec.substr(4), ':');
        if (p.size() != 3) throw std::invalid_argument("a log range is log:start:stop:count");
        const double a = number(p[0], unit_of);
        const double b = number(p[1], unit_of);
        if (!(a > 0 && b > 0)) throw std::invalid_argument("a log range needs start and stop > 0");
        std::vector<double> v = linear(std::log(a), std::log(b), count_of(p[2]));
        for (double& x : v) x = std::exp(x);
        v.front() = a;
        if (v.size() > 1) v.back() = b;
        return v;
    }
    if (spec.find(':') != std::string_view::npos) {
        const auto p = split(spec, ':');
        if (p.size() != 3) throw std::invalid_argument("a linear range is start:stop:count");
        return linear(number(p[0], unit_of), number(p[1], unit_of), count_of(p[2]));
    }
    std::vector<double> v;
    for (const std::string& item : split(spec, ',')) v.push_back(number(item, unit_of));
    return v;
}

std::optional<double> finite_number(std::string_view text) {
    const std::string s(text);
    if (s.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (errno != 0 || end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

double parse_value(std::string_view text, std::optional<Dimension> unit_of) { return number(std::string(text), unit_of); }

std::optional<std::pair<double, double>> parse_bounds(std::string_view text, std::optional<Dimension> unit_of) {
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos || text.find(':', colon + 1) != std::string_view::npos) return std::nullopt;
    try {
        return std::make_pair(number(std::string(text.substr(0, colon)), unit_of),
                              number(std::string(text.substr(colon + 1)), unit_of));
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

}  // namespace vi
