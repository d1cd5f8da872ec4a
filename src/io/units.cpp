#include "io/units.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <system_error>

namespace vi {
namespace {

// One accepted unit: its exact (case-sensitive) spelling and the factor to SI. Units not `listed`
// are accepted but left out of accepted_units() (look-alike spellings such as the Greek mu).
struct UnitEntry {
    Dimension dimension;
    std::string_view symbol;
    double factor;
    bool listed;
};

// "\xC2\xB5" is U+00B5 MICRO SIGN, "\xCE\xBC" is U+03BC GREEK SMALL LETTER MU (both in UTF-8).
constexpr UnitEntry kUnits[] = {
    {Dimension::length, "m", 1.0, true},
    {Dimension::length, "mm", 1e-3, true},
    {Dimension::length, "um", 1e-6, true},
    {Dimension::length, "\xC2\xB5" "m", 1e-6, true},
    {Dimension::length, "\xCE\xBC" "m", 1e-6, false},
    {Dimension::length, "nm", 1e-9, true},
    {Dimension::pressure, "Pa", 1.0, true},
    {Dimension::pressure, "kPa", 1e3, true},
    {Dimension::pressure, "MPa", 1e6, true},
    {Dimension::pressure, "GPa", 1e9, true},
    {Dimension::density, "kg/m^3", 1.0, true},
    {Dimension::density, "g/cm^3", 1e3, true},
    {Dimension::stiffness, "N/m", 1.0, true},
    {Dimension::stiffness, "kN/m", 1e3, true},
    {Dimension::damping, "N s/m", 1.0, true},
    {Dimension::damping, "N*s/m", 1.0, true},
    {Dimension::damping, "Ns/m", 1.0, true},
    {Dimension::damping, "kg/s", 1.0, true},
    {Dimension::force, "N", 1.0, true},
    {Dimension::force, "mN", 1e-3, true},
    {Dimension::force, "uN", 1e-6, true},
    {Dimension::force, "\xC2\xB5" "N", 1e-6, true},
    {Dimension::force, "\xCE\xBC" "N", 1e-6, false},
    {Dimension::force, "nN", 1e-9, true},
    {Dimension::time, "s", 1.0, true},
    {Dimension::time, "ms", 1e-3, true},
    {Dimension::time, "us", 1e-6, true},
    {Dimension::time, "\xC2\xB5" "s", 1e-6, true},
    {Dimension::time, "\xCE\xBC" "s", 1e-6, false},
    {Dimension::time, "ns", 1e-9, true},
    {Dimension::velocity, "m/s", 1.0, true},
    {Dimension::velocity, "mm/s", 1e-3, true},
    {Dimension::frequency, "Hz", 1.0, true},
    {Dimension::frequency, "kHz", 1e3, true},
    {Dimension::frequency, "MHz", 1e6, true},
    {Dimension::mass_damping, "1/s", 1.0, true},
    {Dimension::voltage, "V", 1.0, true},
    {Dimension::voltage, "mV", 1e-3, true},
    {Dimension::voltage, "kV", 1e3, true},
    {Dimension::surface_energy, "J/m^2", 1.0, true},
    {Dimension::surface_energy, "mJ/m^2", 1e-3, true},
    {Dimension::viscosity, "Pa s", 1.0, true},
    {Dimension::viscosity, "Pa*s", 1.0, true},
    {Dimension::viscosity, "mPa s", 1e-3, true},
    {Dimension::viscosity, "uPa s", 1e-6, true},
    {Dimension::temperature, "K", 1.0, true},
};

bool is_space(char ch) {
    return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\f' || ch == '\v';
}

bool is_digit(char ch) { return ch >= '0' && ch <= '9'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

// Runs of white space inside a unit count as one space ("N  s/m" is "N s/m").
std::string collapse_spaces(std::string_view s) {
    std::string out;
    bool in_space = false;
    for (const char ch : s) {
        if (is_space(ch)) {
            in_space = true;
            continue;
        }
        if (in_space && !out.empty()) out += ' ';
        in_space = false;
        out += ch;
    }
    return out;
}

// Length of the C-style decimal number at the start of s (sign, digits with an optional point,
// optional exponent), or 0 when s does not start with one.
std::size_t number_length(std::string_view s) {
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < s.size() && is_digit(s[i])) ++i, ++digits;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && is_digit(s[i])) ++i, ++digits;
    }
    if (digits == 0) return 0;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        std::size_t j = i + 1;
        if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
        if (j < s.size() && is_digit(s[j])) {
            while (j < s.size() && is_digit(s[j])) ++j;
            i = j;
        }
    }
    return i;
}

// True when s spells an infinity or a NaN the way strtod would accept it ("inf", "-NaN", ...).
bool looks_non_finite(std::string_view s) {
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) s.remove_prefix(1);
    if (s.size() < 3) return false;
    std::string head;
    for (std::size_t i = 0; i < 3; ++i) head += static_cast<char>(s[i] | 0x20);
    return head == "inf" || head == "nan";
}

[[noreturn]] void fail(const std::string& reason) { throw std::invalid_argument(reason); }

std::string unit_list_for(Dimension d) {
    return std::string(dimension_name(d)) + ": " + accepted_units(d);
}

}  // namespace

std::string_view dimension_name(Dimension d) {
    switch (d) {
        case Dimension::dimensionless: return "dimensionless";
        case Dimension::length: return "a length";
        case Dimension::pressure: return "a pressure";
        case Dimension::density: return "a density";
        case Dimension::stiffness: return "a stiffness";
        case Dimension::damping: return "a damping coefficient";
        case Dimension::force: return "a force";
        case Dimension::time: return "a time";
        case Dimension::velocity: return "a velocity";
        case Dimension::frequency: return "a frequency";
        case Dimension::mass_damping: return "a mass-proportional damping rate";
        case Dimension::voltage: return "a voltage";
        case Dimension::surface_energy: return "an energy per area";
        case Dimension::viscosity: return "a viscosity";
        case Dimension::temperature: return "a temperature";
    }
    return "a quantity";
}

std::string accepted_units(Dimension d) {
    if (d == Dimension::dimensionless) return "none (a plain number)";
    std::string out;
    for (const UnitEntry& u : kUnits) {
        if (u.dimension != d || !u.listed) continue;
        if (!out.empty()) out += ", ";
        out += u.symbol;
    }
    return out;
}

std::string in_quotes(std::string_view text) {
    std::string out = "\"";
    for (const char ch : text) {
        const auto byte = static_cast<unsigned char>(ch);
        if (ch == '"' || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (ch == '\n') {
            out += "\\n";
        } else if (ch == '\t') {
            out += "\\t";
        } else if (ch == '\r') {
            out += "\\r";
        } else if (byte < 0x20 || byte == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(byte));
            out += buf;
        } else {
            out += ch;
        }
    }
    out += '"';
    return out;
}

double parse_quantity(std::string_view text, Dimension d) {
    const std::string_view s = trim(text);
    if (s.empty()) {
        if (d == Dimension::dimensionless) fail("empty value (expected a number)");
        fail("empty value (expected a number and a unit, one of " + accepted_units(d) + ")");
    }

    const std::size_t n = number_length(s);
    if (n == 0) {
        if (looks_non_finite(s)) fail("infinite and NaN values are not allowed");
        fail("expected a number at the start of " + in_quotes(s));
    }
    std::string_view digits = s.substr(0, n);
    if (digits.front() == '+') digits.remove_prefix(1);  // from_chars takes no '+'
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) fail("number " + in_quotes(s.substr(0, n)) + " is out of range");
    if (ec != std::errc() || end != digits.data() + digits.size()) {
        fail("expected a number at the start of " + in_quotes(s));
    }

    const std::string unit = collapse_spaces(s.substr(n));
    if (d == Dimension::dimensionless) {
        if (!unit.empty()) fail("a dimensionless value takes no unit, got " + in_quotes(unit));
        return value;
    }
    if (unit.empty()) fail("missing unit (expected " + unit_list_for(d) + ")");

    for (const UnitEntry& u : kUnits) {
        if (u.dimension == d && u.symbol == unit) {
            const double si = value * u.factor;
            if (!std::isfinite(si)) fail("value " + in_quotes(s) + " is out of range");
            return si;
        }
    }
    for (const UnitEntry& u : kUnits) {
        if (u.symbol == unit) {
            fail("unit " + in_quotes(unit) + " is " + std::string(dimension_name(u.dimension)) + ", expected " +
                 unit_list_for(d));
        }
    }
    fail("unknown unit " + in_quotes(unit) + " (expected " + unit_list_for(d) + ")");
}

}  // namespace vi
