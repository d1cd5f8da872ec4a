#pragma once
// What the commands that draw figures share: finding gnuplot, and writing the result files together
// with the rendered figures in one step.

#include <optional>
#include <string>
#include <vector>

#include "io/output_files.hpp"
#include "plot/figure_gnuplot.hpp"

namespace vi::cli {

// The gnuplot to run; throws std::runtime_error naming what it draws and how to install it.
std::string require_gnuplot(const std::string& requested, const std::string& what);

// Renders `figures`, adds their files to `files`, checks for a stop, and writes everything into dir
// at once (a CommitSection: a second signal waits until the files are in place). When the figures
// cannot be drawn or read back (gnuplot fails, writes no image, or one too large to read), the
// other files are written all the same, with each figure's data and script but no image, and the
// reason is returned (one line) for the caller to report; nullopt when everything was written.
[[nodiscard]] std::optional<std::string> write_with_figures(const std::string& dir, OutputFiles files,
                                                            const std::vector<FigureSpec>& figures, const std::string& gnuplot);

}  // namespace vi::cli
