#pragma once
// A beam's deflection over time as a VTK XML time series that ParaView opens: one UnstructuredGrid
// file (.vtu, ASCII) per frame and a collection (.pvd) naming each frame's time.

#include <string>
#include <vector>

#include "io/output_files.hpp"

namespace vi {

// One frame: the time [s] and, per node, the transverse deflection v [m] and rotation theta [rad].
struct BeamFrame {
    double t = 0.0;
    std::vector<double> v;
    std::vector<double> theta;
};

// The series of a straight beam along x: nodes at (x, 0, 0) [m] joined by line cells, each frame's
// point data "displacement" (0, v, 0) [m] (ParaView's Warp By Vector draws the deflected beam),
// "deflection_m" and "rotation_rad". Returns `stem`.pvd and `stem`/`stem`_NNNNN.vtu (names relative
// to the output folder). Throws std::invalid_argument when a frame's length is not the node count.
OutputFiles vtk_beam_series(const std::string& stem, const std::vector<double>& x, const std::vector<BeamFrame>& frames);

}  // namespace vi
