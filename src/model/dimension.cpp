#include "model/dimension.hpp"

namespace vi {

std::string_view si_unit(Dimension d) {
    switch (d) {
        case Dimension::dimensionless: return "-";
        case Dimension::length: return "m";
        case Dimension::pressure: return "Pa";
        case Dimension::density: return "kg/m^3";
        case Dimension::stiffness: return "N/m";
        case Dimension::damping: return "N s/m";
        case Dimension::force: return "N";
        case Dimension::time: return "s";
        case Dimension::velocity: return "m/s";
        case Dimension::frequency: return "Hz";
        case Dimension::mass_damping: return "1/s";
        case Dimension::voltage: return "V";
        case Dimension::surface_energy: return "J/m^2";
        case Dimension::viscosity: return "Pa s";
        case Dimension::temperature: return "K";
    }
    return "-";
}

std::string_view dimension_label(Dimension d) {
    switch (d) {
        case Dimension::dimensionless: return "dimensionless";
        case Dimension::length: return "length";
        case Dimension::pressure: return "pressure";
        case Dimension::density: return "density";
        case Dimension::stiffness: return "stiffness";
        case Dimension::damping: return "damping coefficient";
        case Dimension::force: return "force";
        case Dimension::time: return "time";
        case Dimension::velocity: return "velocity";
        case Dimension::frequency: return "frequency";
        case Dimension::mass_damping: return "mass-proportional damping rate";
        case Dimension::voltage: return "voltage";
        case Dimension::surface_energy: return "energy per area";
        case Dimension::viscosity: return "viscosity";
        case Dimension::temperature: return "temperature";
    }
    return "dimensionless";
}

}  // namespace vi
