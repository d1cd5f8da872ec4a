#pragma once
// Dimension: the physical dimension of a case value, with its SI unit and its name in the docs.

#include <string_view>

namespace vi {

// The physical dimension a case-file value must have; each accepts only its own units (io/units.hpp).
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

// The SI unit of d as the program writes it ("m", "N s/m", "kg/m^3"); "-" when dimensionless.
std::string_view si_unit(Dimension d);

// d as the docs' table of units names it ("length", "damping coefficient", "dimensionless").
std::string_view dimension_label(Dimension d);

}  // namespace vi
