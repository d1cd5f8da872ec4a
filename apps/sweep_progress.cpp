#include "sweep_progress.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

namespace vi::cli {
namespace {

std::string duration_text(double s) {
    const long t = static_cast<long>(s + 0.5);
    char buf[32];
    if (t >= 3600) {
        std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
    } else {
        std::snprintf(buf, sizeof buf, "%ld:%02ld", t / 60, t % 60);
    }
    return buf;
}

}  // namespace

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

SweepProgress::SweepProgress(std::size_t total, std::size_t already_done, bool enabled)
    : total_(total), done_(already_done), enabled_(enabled && total > 0) {
    if (enabled_) draw();
}

void SweepProgress::point_done() {
    const std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    ++computed_;
    if (enabled_ && Clock::now() - last_draw_ > std::chrono::milliseconds(200)) draw();
}

void SweepProgress::tick(const RunningPoints& running) {
    const auto [index, seconds] = running.slowest();
    const std::lock_guard<std::mutex> lock(mutex_);
    slow_.clear();
    if (index != SIZE_MAX && seconds >= 2.0) {
        slow_ = "  slowest: point " + std::to_string(index) + ", " + duration_text(seconds) + " running";
    }
    if (enabled_) draw();
}

ProgressTicker::ProgressTicker(SweepProgress& progress, const RunningPoints& running) {
    if (!stderr_is_terminal()) return;
    thread_ = std::thread([this, &progress, &running]() {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(500), [this] { return done_; })) {
            progress.tick(running);
        }
    });
}

ProgressTicker::~ProgressTicker() {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        done_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void SweepProgress::finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!enabled_) return;
    draw();
    std::fputc('\n', stderr);
    std::fflush(stderr);
}

void SweepProgress::draw() {
    last_draw_ = Clock::now();
    constexpr std::size_t kWidth = 30;
    const std::size_t filled = total_ ? done_ * kWidth / total_ : kWidth;
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    const double elapsed = std::chrono::duration<double>(last_draw_ - start_).count();
    std::string rate = "-";
    std::string left = "-";
    if (computed_ > 0 && elapsed > 0.0) {
        const double per_s = static_cast<double>(computed_) / elapsed;
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3g/s", per_s);
        rate = buf;
        left = duration_text(static_cast<double>(total_ - done_) / per_s);
    }
    // \r and "erase to end of line": the line is redrawn in place.
    std::fprintf(stderr, "\r\033[Ksweep [%s] %zu/%zu points  %s  left %s  elapsed %s%s", bar.c_str(), done_, total_,
                 rate.c_str(), left.c_str(), duration_text(elapsed).c_str(), slow_.c_str());
    std::fflush(stderr);
}

}  // namespace vi::cli
