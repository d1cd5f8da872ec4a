#pragma once
// Peak resident memory of a bench process (getrusage's ru_maxrss), printed as its last line when it
// exits: every bench says how much memory its runs took.

#include <sys/resource.h>

#include <cstdio>

namespace vi_bench {

// Largest resident set of this process so far [MiB] (Linux reports ru_maxrss in KiB).
inline double peak_rss_mib() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

struct PrintPeakRssAtExit {
    PrintPeakRssAtExit() = default;
    PrintPeakRssAtExit(const PrintPeakRssAtExit&) = delete;
    PrintPeakRssAtExit& operator=(const PrintPeakRssAtExit&) = delete;
    ~PrintPeakRssAtExit() {
        std::printf("peak RSS: %.1f MiB\n", peak_rss_mib());
        std::fflush(stdout);
    }
};
// One per program (an inline variable): destroyed, and so printed, after main returns.
inline PrintPeakRssAtExit print_peak_rss_at_exit;

}  // namespace vi_bench
