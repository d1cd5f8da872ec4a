#include "progress.hpp"

#include <unistd.h>

namespace vi::cli {

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

CLI::Option* add_progress_options(CLI::App& sub, ProgressSettings& s) {
    CLI::Option* mode = sub.add_option("--progress", s.mode,
                   "Progress on stderr: auto (a bar on a terminal, lines otherwise), bar, lines or none "
                   "(default: $VIBROIMPACT_PROGRESS, else auto)")
        ->check(CLI::IsMember({"auto", "bar", "lines", "none"}));
    sub.add_option("--progress-interval", s.interval_s, "Seconds between two progress lines (0: a line at every step)")
        ->check(CLI::Range(0.0, 1e6))
        ->capture_default_str();
    return mode;
}

ProgressStyle progress_style(const ProgressSettings& s) {
    return progress_style_named(s.mode, stderr_is_terminal(), "--progress");
}

}  // namespace vi::cli
