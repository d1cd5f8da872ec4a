#pragma once
// The figures of each kind of run folder (internal to study/run_plots; run_plots.hpp is the entry).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "plot/figure_gnuplot.hpp"

namespace vi {

// A simulate folder (history.csv, summary.json): displacements, velocities, forces, energies and any
// other quantity against time, one figure per unit, and the tip's phase portrait. Columns without a
// finite value are added to `skipped`.
std::vector<FigureSpec> transient_figures(const std::string& dir, std::vector<std::string>& skipped);

// A modes folder (shapes_unsupported.csv, shapes_supported.csv, modes.json): the mode shapes of each,
// scaled to a peak of 1, with their nodal points marked.
std::vector<FigureSpec> modes_figures(const std::string& dir);

// A sweep folder (sweep.csv, sweep.json): each numeric reported quantity against the one varying axis,
// or as a heat map over two. Columns not drawn (text, no finite value) are added to `skipped` with the reason.
std::vector<FigureSpec> sweep_figures(const std::string& dir, std::vector<std::string>& skipped);

// The most frames an animation of the field holds; a longer field is thinned evenly, first and last kept.
inline constexpr std::size_t kMaxAnimationFrames = 300;

// Which of `frames` frames an animation shows (indices ascending; at most kMaxAnimationFrames).
std::vector<std::size_t> animation_frames(std::size_t frames);

// A simulate folder's field (field.csv, simulate --field) as an animated GIF of the deflected beam,
// titled with the case's name; none when the folder has no field.csv.
std::vector<FigureSpec> field_figures(const std::string& dir, const std::string& case_name);

// The JSON file at path; null when it does not exist. Throws InputError naming the file when it
// exists but cannot be read or parsed.
nlohmann::json read_run_json(const std::string& path);

}  // namespace vi
