#pragma once
// The progress line of a sweep on stderr: a bar, points done of all, the rate and the time left.

#include <chrono>
#include <string>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>

#include "sweep/runner.hpp"

namespace vi::cli {

// Redrawn in place at most a few times a second; draws nothing when disabled (stderr not a
// terminal, or not the MPI root), so logs and pipes stay clean.
class SweepProgress {
public:
    // total: points of the grid; already_done: taken over from a journal (not in the rate).
    SweepProgress(std::size_t total, std::size_t already_done, bool enabled);
    // One more point finished.
    void point_done();
    // Redraws with the point that has been running longest (shown once it passes 2 s).
    void tick(const RunningPoints& running);
    // Draws the final state and ends the line.
    void finish();

private:
    void draw();  // under mutex_
    using Clock = std::chrono::steady_clock;
    std::size_t total_;
    std::size_t done_;
    std::size_t computed_ = 0;
    bool enabled_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_draw_{};
    std::mutex mutex_;  // point_done (worker threads) and tick (the ticker) draw the same line
    std::string slow_;  // "slowest: point N, S s running", or empty
};

// Calls progress.tick(running) twice a second on a thread of its own while it lives (only when
// stderr is a terminal: otherwise nothing is drawn anyway and no thread starts).
class ProgressTicker {
public:
    ProgressTicker(SweepProgress& progress, const RunningPoints& running);
    ~ProgressTicker();
    ProgressTicker(const ProgressTicker&) = delete;
    ProgressTicker& operator=(const ProgressTicker&) = delete;

private:
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::thread thread_;
};

// True when stderr is a terminal.
bool stderr_is_terminal();

}  // namespace vi::cli
