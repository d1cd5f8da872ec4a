#pragma once
// Mutates a case file the way a switch designer edits one, for the fuzz test of every physics: a
// second electrode, a contact stop removed, electrodes run to the beam's ends, an electrode gap below
// the stop's gap, voltages from 0 to 3 V_PI, waveforms at extreme rates (a voltage table written
// beside the case), air, dielectric layers, adhesion, meshes, end conditions, solver settings, and
// values set to magnitudes at the ends of the accepted range (1e-300, 1e300) in their own units.

#include <cstdint>
#include <string>

#include "support/case_mutator.hpp"

namespace vi::test {

// What a mutation needs to know of the original case.
struct DesignerSource {
    std::string text;
    double pullin_voltage = 0.0;  // V_PI of the unmutated case [V]; 0 when it has none
};

// Deterministic: the same source, seed and index always give the same mutant (1 to 3 edits). Files
// the mutant refers to by name (a voltage table) are in Mutant::files.
Mutant mutate_design(const DesignerSource& source, std::uint64_t seed, std::uint64_t index);

}  // namespace vi::test
