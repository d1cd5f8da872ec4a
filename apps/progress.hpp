#pragma once
// The command line's progress settings (--progress, --progress-interval); the report itself is
// io/progress_report.hpp's.

#include <string>

#include <CLI/CLI.hpp>

#include "io/progress_report.hpp"

namespace vi::cli {

using vi::duration_text;
using vi::kProgressEnvironment;
using vi::Progress;
using vi::ProgressStyle;
using vi::ProgressTicker;

// The command-line settings of the progress report.
struct ProgressSettings {
    std::string mode;         // --progress: auto, bar, lines or none; empty: VIBROIMPACT_PROGRESS, else auto
    double interval_s = 10.0; // --progress-interval: seconds between two lines [s]; 0: a line at every step
};

// Adds --progress and --progress-interval to a command; returns --progress.
CLI::Option* add_progress_options(CLI::App& sub, ProgressSettings& s);

// The style the settings ask for: auto is a bar when stderr is a terminal and lines otherwise.
// Throws InputError for a mode (of VIBROIMPACT_PROGRESS) that is none of the four.
ProgressStyle progress_style(const ProgressSettings& s);

// True when stderr is a terminal.
bool stderr_is_terminal();

}  // namespace vi::cli
