#pragma once
// Quantities written with a unit ("117 um", "207 GPa") converted to SI, with a strict list of units.

#include <string>
#include <string_view>

namespace vi {

// The physical dimension a case-file value must have; each accepts only its own units.
enum class Dimension {
    dimensionless,  // no unit
    length,         // m
    pressure,       // Pa
    density,        // kg/m^3
    stiffness,      // N/m
    damping,        // N s/m
    force,          // N
    time,           // s
    velocity,       // m/s
    frequency,      // Hz
    mass_damping,   // 1/s (Rayleigh alpha)
    voltage,        // V
    surface_energy, // J/m^2 (work of adhesion)
    viscosity,      // Pa s
    temperature,    // K
};

// Human-readable list of the units accepted for a dimension, e.g. "m, mm, um, nm".
std::string accepted_units(Dimension d);

// Parses "<number> <unit>" (space optional) into SI; throws std::invalid_argument with a one-line
// reason when the number or unit is malformed, the unit is not one of d's, or the value is not finite.
double parse_quantity(std::string_view text, Dimension d);

// Name of a dimension for messages, with its article: "a length", "a pressure", "dimensionless".
std::string_view dimension_name(Dimension d);

// text in double quotes, with quotes, backslashes and control characters escaped, so that a message
// quoting user input stays on one line.
std::string in_quotes(std::string_view text);

}  // namespace vi
