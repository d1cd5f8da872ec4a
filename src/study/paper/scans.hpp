#pragma once
// The single runs the paper study is made of: one transient or one modal analysis each, so that the
// study can hand them to worker threads in one batch.

#include <vector>

#include "study/paper/study.hpp"
#include "model/case.hpp"

namespace vi {

// One transient of a scan, c already changed (support moved or prestressed). Never throws: a run
// that fails keeps its one-line reason in error.
TransientPoint run_transient_point(const Case& c, double x);

// Supported modes (support as a pin) with supports[0] at x0/l; free_omega: the unsupported circular
// frequencies [rad/s] the ratios divide by. Never throws.
ModalPoint run_modal_point(const Case& c, double x0, int modes, const std::vector<double>& free_omega);

// Modes of the unsupported beam with sampled shapes (8 points per element).
FreeModes run_free_modes(const Case& c, int modes);

// The case's own transient with the free end's history (Fig. 3).
TypicalTransient run_typical_transient(const Case& c);

// Contact force during the first impact with supports[0] at x0/l (Fig. 11), sampled every 2.5 ns.
ImpactForce run_impact_force(const Case& c, double x0);

// omega_1 with supports[0] as a pin at x0/l [rad/s].
double pinned_first_omega(const Case& c, double x0);

// Largest omega_1(pinned at x0) / omega1_free over x0 in [lo, hi] by golden-section search to
// 1e-9 in x0/l (the ratio has a single maximum inside a bracket taken from a scan).
RatioPeak find_ratio_peak(const Case& c, double omega1_free, double lo, double hi);

}  // namespace vi
