// parse_quantity: every accepted unit converts to SI; wrong, unknown, missing units and non-numbers fail.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "io/units.hpp"

namespace {

using vi::Dimension;
using vi::parse_quantity;

// a == b within a relative tolerance of 1e-15.
void expect_si(const std::string& text, Dimension d, double expected) {
    SCOPED_TRACE(text);
    const double got = parse_quantity(text, d);
    EXPECT_LE(std::abs(got - expected), 1e-15 * std::abs(expected)) << got << " vs " << expected;
}

// parse_quantity throws, and its reason contains `part`.
void expect_rejected(const std::string& text, Dimension d, const std::string& part = "") {
    SCOPED_TRACE(text);
    try {
        parse_quantity(text, d);
        FAIL() << "accepted " << text;
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(part), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(Units, Length) {
    expect_si("117 um", Dimension::length, 117e-6);
    expect_si("117um", Dimension::length, 117e-6);
    expect_si("  2 um  ", Dimension::length, 2e-6);
    expect_si("1.5 m", Dimension::length, 1.5);
    expect_si("3 mm", Dimension::length, 3e-3);
    expect_si("30 \xC2\xB5m", Dimension::length, 30e-6);  // U+00B5 micro sign
    expect_si("30 \xCE\xBCm", Dimension::length, 30e-6);  // U+03BC Greek mu
    expect_si("250 nm", Dimension::length, 250e-9);
    expect_si("-1.5e-1 mm", Dimension::length, -1.5e-4);
    expect_si("+.5 m", Dimension::length, 0.5);
}

TEST(Units, Pressure) {
    expect_si("207 GPa", Dimension::pressure, 207e9);
    expect_si("160 MPa", Dimension::pressure, 160e6);
    expect_si("3 kPa", Dimension::pressure, 3e3);
    expect_si("101325 Pa", Dimension::pressure, 101325.0);
}

TEST(Units, Density) {
    expect_si("8902 kg/m^3", Dimension::density, 8902.0);
    expect_si("8.902 g/cm^3", Dimension::density, 8902.0);
}

TEST(Units, StiffnessAndDamping) {
    expect_si("50 N/m", Dimension::stiffness, 50.0);
    expect_si("1.5 kN/m", Dimension::stiffness, 1500.0);
    expect_si("1e-7 N s/m", Dimension::damping, 1e-7);
    expect_si("1e-7 N  s/m", Dimension::damping, 1e-7);
    expect_si("2e-7 N*s/m", Dimension::damping, 2e-7);
    expect_si("3e-7 Ns/m", Dimension::damping, 3e-7);
    expect_si("4e-7 kg/s", Dimension::damping, 4e-7);
}

TEST(Units, ForceTimeVelocityFrequency) {
    expect_si("2 N", Dimension::force, 2.0);
    expect_si("2 mN", Dimension::force, 2e-3);
    expect_si("2 uN", Dimension::force, 2e-6);
    expect_si("2 \xC2\xB5N", Dimension::force, 2e-6);
    expect_si("2 \xCE\xBCN", Dimension::force, 2e-6);
    expect_si("2 nN", Dimension::force, 2e-9);
    expect_si("4 s", Dimension::time, 4.0);
    expect_si("4 ms", Dimension::time, 4e-3);
    expect_si("4 us", Dimension::time, 4e-6);
    expect_si("4 \xC2\xB5s", Dimension::time, 4e-6);
    expect_si("4 \xCE\xBCs", Dimension::time, 4e-6);
    expect_si("4 ns", Dimension::time, 4e-9);
    expect_si("0.3 m/s", Dimension::velocity, 0.3);
    expect_si("300 mm/s", Dimension::velocity, 0.3);
    expect_si("50 Hz", Dimension::frequency, 50.0);
    expect_si("50 kHz", Dimension::frequency, 5e4);
    expect_si("1.2 MHz", Dimension::frequency, 1.2e6);
    expect_si("100 1/s", Dimension::mass_damping, 100.0);
}

TEST(Units, Dimensionless) {
    expect_si("0.5", Dimension::dimensionless, 0.5);
    expect_si(" 1e-2 ", Dimension::dimensionless, 1e-2);
    expect_rejected("0.5 um", Dimension::dimensionless, "takes no unit");
}

TEST(Units, WrongDimensionNamesBoth) {
    expect_rejected("207 GPa", Dimension::length, "unit \"GPa\" is a pressure, expected a length: m, mm, um");
    expect_rejected("2 um", Dimension::pressure, "is a length");
    expect_rejected("50 N/m", Dimension::damping, "is a stiffness");
    expect_rejected("1 s", Dimension::mass_damping, "is a time");
}

TEST(Units, UnknownUnitListsAccepted) {
    expect_rejected("2 furlongs", Dimension::length, "unknown unit \"furlongs\" (expected a length: " +
                                                         vi::accepted_units(Dimension::length) + ")");
    expect_rejected("2 UM", Dimension::length, "unknown unit");   // case matters
    expect_rejected("207 gpa", Dimension::pressure, "unknown unit");
    expect_rejected("1 mPa", Dimension::pressure, "unknown unit");  // milli, not mega
    expect_rejected("8902 kg/m3", Dimension::density, "unknown unit");
    expect_rejected("2 um extra", Dimension::length, "unknown unit");
}

TEST(Units, MissingUnitAndEmpty) {
    expect_rejected("117", Dimension::length, "missing unit");
    expect_rejected("", Dimension::length, "empty");
    expect_rejected("   ", Dimension::length, "empty");
    expect_rejected("", Dimension::dimensionless, "empty");
}

TEST(Units, NonFiniteRejected) {
    expect_rejected("nan", Dimension::dimensionless, "NaN");
    expect_rejected("inf", Dimension::dimensionless, "NaN");
    expect_rejected("-inf um", Dimension::length, "infinite");
    expect_rejected("NaN m", Dimension::length, "infinite");
    expect_rejected("infinity", Dimension::dimensionless, "infinite");
    expect_rejected("1e999", Dimension::dimensionless, "out of range");
    expect_rejected("1e999 um", Dimension::length, "out of range");
    expect_rejected("1e-999 um", Dimension::length, "out of range");
    expect_rejected("1e308 GPa", Dimension::pressure, "out of range");
}

TEST(Units, GarbageRejected) {
    expect_rejected("um", Dimension::length, "expected a number");
    expect_rejected("abc", Dimension::dimensionless, "expected a number");
    expect_rejected(".", Dimension::length, "expected a number");
    expect_rejected("-", Dimension::length, "expected a number");
    expect_rejected("e5 m", Dimension::length, "expected a number");
    expect_rejected("0x10", Dimension::dimensionless, "takes no unit");
    expect_rejected("1,5 mm", Dimension::length, "unknown unit");
    expect_rejected("1\nm", Dimension::dimensionless, "takes no unit");
    expect_rejected(std::string("1 m\0m", 5), Dimension::length, "\\x00");
}

TEST(Units, AcceptedUnitsList) {
    EXPECT_EQ(vi::accepted_units(Dimension::length), "m, mm, um, \xC2\xB5m, nm");
    EXPECT_EQ(vi::accepted_units(Dimension::pressure), "Pa, kPa, MPa, GPa");
    EXPECT_EQ(vi::accepted_units(Dimension::mass_damping), "1/s");
}

TEST(Units, QuotedEscapesControlCharacters) {
    EXPECT_EQ(vi::in_quotes("a\"b\\c\nd\x01"), "\"a\\\"b\\\\c\\nd\\x01\"");
}

}  // namespace
