#pragma once
// The whole beam over time (TimeHistory's field) as files: field.csv, and field.pvd with field/*.vtu
// for ParaView (io/vtk_series.hpp).

#include <vector>

#include "dynamics/transient_result.hpp"
#include "fem/system.hpp"
#include "io/csv_writer.hpp"
#include "io/output_files.hpp"
#include "io/vtk_series.hpp"

namespace vi {

// The beam's deflection at each node [m] and its rotation [rad] in every frame of the history's
// field (zero at constrained DOFs); `x` the node coordinates [m].
struct BeamField {
    std::vector<double> x;
    std::vector<BeamFrame> frames;
};

// The field of `h` over the system's nodes (bending DOFs in the order of s.bending); empty frames
// when the history has no field.
BeamField beam_field(const System& s, const TimeHistory& h);

// One row per node and frame: frame, t_s, x_m, v_m, theta_rad.
CsvTable field_csv(const BeamField& f);

// field.csv, field.pvd and field/field_NNNNN.vtu; nothing when the field has no frames.
OutputFiles field_files(const BeamField& f);

}  // namespace vi
