#pragma once
// The data of a report page's animated beam (report_charts.js draws it as SVG, no network): the
// deflected beam of a transient's field, frame by frame.

#include <cstddef>
#include <string>

#include "report/field_output.hpp"

namespace vi {

// The most frames a page carries; a longer field is thinned evenly, first and last kept.
inline constexpr std::size_t kMaxPageFrames = 300;

// JSON text: "x" node positions [m], "t" the frames' times [s], "v" per frame the deflection of each
// node [m] (6 significant digits), "surfaces" the supports' surfaces as [x, height] pairs [m];
// '<' never appears, so that it can sit inside a <script> element. Throws std::invalid_argument
// when the field has no frames.
std::string beam_animation_json(const BeamField& f, const std::vector<std::pair<double, double>>& surfaces = {});

}  // namespace vi
