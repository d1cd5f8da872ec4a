#pragma once
// A measured trajectory of one point of the beam (a laser vibrometer's record): CSV with a header
// row, time t_s [s], the measured column (tip_m [m] or tip_velocity_m_s [m/s]) and optionally the
// noise level of each sample, sigma (same unit), in any column order.

#include <cstddef>
#include <string>
#include <vector>

namespace vi {

struct MeasuredTrajectory {
    std::string file;
    std::string column;          // "tip_m" or "tip_velocity_m_s"
    std::vector<double> t;       // strictly increasing [s]
    std::vector<double> value;   // [m] or [m/s]
    std::vector<double> sigma;   // per-sample noise level (> 0), or empty
    std::vector<std::size_t> line;  // each sample's line in the file (for messages), or empty
};

// Reads `path`. Throws InputError("FILE:LINE: reason") for an unreadable file, a missing or
// repeated column, a cell that is not a finite number or whose nonzero magnitude lies outside the
// window double precision computes with here (1e-100 .. 1e100, model/run_estimate.hpp), times not
// strictly increasing, sigma not positive, or fewer than min_rows samples.
MeasuredTrajectory read_measured_trajectory(const std::string& path, const std::string& column, std::size_t min_rows);

}  // namespace vi
