#pragma once
// The stiction check of an electrode's adhesive dielectric layer: the peel balance of the beam held
// down on it with no voltage, and the FE beam laid on it and let settle (docs/adhesion.md §10).

#include <optional>
#include <vector>

#include "statics/layer_hold.hpp"
#include "model/case.hpp"

namespace vi {

struct LayerStiction {
    LayerHold hold;  // the peel balance: rigid layer, zero range, the beam alone
    // The case's FE model (its static elements: supports, layers, stretching; no voltage) laid flat on
    // the layer's face over its span and let settle downhill with the layer's full law
    // (minimize_static_energy): whether it still touches the layer, and where [m].
    bool settled_stuck = false;
    double settled_from = 0.0, settled_to = 0.0;
    // A cantilever (one end free): the S-shape's detached length from the held end, by the closed
    // form (rigid layer), on the compliant layer in the limit of zero range (detached_length_on_layer),
    // and of the settled FE beam (where it first touches, from the held end; empty when released) [m].
    std::optional<double> detached_closed_form, detached_on_layer, detached_settled;
};

// One entry per electrode with an adhesive layer, in case order (empty when none has one). The case
// must pass check_case.
std::vector<LayerStiction> layer_stiction(const Case& c);

}  // namespace vi
