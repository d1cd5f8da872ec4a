#pragma once
// The progress line of a sweep on stderr: a bar, points done of all, the rate and the time left.

#include <chrono>
#include <cstddef>

namespace vi::cli {

// Redrawn in place at most a few times a second; draws nothing when disabled (stderr not a
// terminal, or not the MPI root), so logs and pipes stay clean.
class SweepProgress {
public:
    // total: points of the grid; already_done: taken over from a journal (not in the rate).
    SweepProgress(std::size_t total, std::size_t already_done, bool enabled);
    // One more point finished; calls come one at a time.
    void point_done();
    // Draws the final state and ends the line.
    void finish();

private:
    void draw();
    using Clock = std::chrono::steady_clock;
    std::size_t total_;
    std::size_t done_;
    std::size_t computed_ = 0;
    bool enabled_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_draw_{};
};

// True when stderr is a terminal.
bool stderr_is_terminal();

}  // namespace vi::cli
