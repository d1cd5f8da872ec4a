#include "io/progress_report.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi {

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

ProgressStyle progress_style_named(const std::string& mode, bool terminal, const std::string& setting) {
    std::string m = mode;
    const bool from_environment = m.empty();
    if (from_environment) {
        const char* env = std::getenv(kProgressEnvironment);
        m = env != nullptr && *env != '\0' ? env : "auto";
    }
    if (m == "auto") return terminal ? ProgressStyle::bar : ProgressStyle::lines;
    if (m == "bar") return ProgressStyle::bar;
    if (m == "lines") return ProgressStyle::lines;
    if (m == "none") return ProgressStyle::none;
    if (from_environment) throw InputError(std::string(kProgressEnvironment) + "=" + m + ": must be auto, bar, lines or none");
    throw InputError(setting + ": must be auto, bar, lines or none (got \"" + m + "\")");
}

Progress::Progress(std::string what, std::string unit, std::size_t total, std::size_t done, ProgressStyle style,
                   double interval_s, bool upper_bound, ProgressSink sink)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      total_(total),
      done_(done),
      shown_(done),
      style_(style),
      interval_s_(interval_s),
      upper_bound_(upper_bound),
      sink_(std::move(sink)) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (style_ == ProgressStyle::bar) draw_bar();
}

Progress::~Progress() { finish(); }

void Progress::advance(std::size_t n) { count(n, n); }

void Progress::skip(std::size_t n) { count(n, 0); }

void Progress::emit(const std::string& text) {
    if (sink_) {
        sink_(text);
        return;
    }
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
}

void Progress::count(std::size_t done, std::size_t computed) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (finished_ || done == 0) return;
    done_ = std::min(done_ + done, total_);
    computed_ += computed;
    const double since = seconds_since(last_);
    if (style_ == ProgressStyle::bar && since > 0.2) draw_bar();
    if (style_ == ProgressStyle::lines && (interval_s_ == 0.0 || since >= interval_s_)) write_line();
}

void Progress::set_total(std::size_t total) {
    const std::lock_guard<std::mutex> lock(mutex_);
    total_ = total;
    done_ = std::min(done_, total_);
    shown_ = std::min(shown_, total_);
    if (style_ == ProgressStyle::bar && !finished_) draw_bar();
}

void Progress::say(const std::string& line) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (style_ == ProgressStyle::none) return;
    // Over the bar, which is drawn again below the line.
    emit((drawn_ ? "\r\033[K" : "") + line + "\n");
    if (drawn_ && !finished_) draw_bar();
}

void Progress::set_note(const std::string& note) {
    const std::lock_guard<std::mutex> lock(mutex_);
    note_ = note;
}

void Progress::tick() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return;
    if (style_ == ProgressStyle::bar) draw_bar();
    // At interval 0 lines follow the steps alone (a test can count them); otherwise a line comes at
    // least every interval, so that a log shows the run alive while a step is slow.
    if (style_ == ProgressStyle::lines && interval_s_ > 0.0 && seconds_since(last_) >= interval_s_) write_line();
}

void Progress::finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return;
    if (style_ == ProgressStyle::bar && total_ > 0) {
        draw_bar();
        emit("\n");
    }
    if (style_ == ProgressStyle::lines && wrote_line_ && shown_ != done_) write_line();
    finished_ = true;
    drawn_ = false;
}

std::string Progress::counts() const {
    const double elapsed = seconds_since(start_);
    std::string rate = "- " + unit_ + "/s", left = "-";
    if (computed_ > 0 && elapsed > 0.0) {
        const double per_s = static_cast<double>(computed_) / elapsed;
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.3g", per_s);
        rate = std::string(buf) + " " + unit_ + "/s";
        left = (upper_bound_ ? "at most " : "") + duration_text(static_cast<double>(total_ - done_) / per_s);
    }
    const std::string sep = style_ == ProgressStyle::bar ? "  " : ", ";
    return std::to_string(done_) + "/" + std::to_string(total_) + " " + unit_ + sep + rate + sep + "left " + left + sep +
           "elapsed " + duration_text(elapsed);
}

void Progress::draw_bar() {
    if (total_ == 0) return;  // nothing to count yet
    last_ = Clock::now();
    drawn_ = true;
    constexpr std::size_t kWidth = 30;
    std::string bar(done_ * kWidth / total_, '#');
    bar.resize(kWidth, '.');
    // \r and "erase to end of line": the line is redrawn in place.
    emit("\r\033[K" + what_ + " [" + bar + "] " + counts() + (note_.empty() ? "" : "  ") + note_);
}

void Progress::write_line() {
    if (total_ == 0) return;
    last_ = Clock::now();
    shown_ = done_;
    wrote_line_ = true;
    emit(what_ + ": " + counts() + (note_.empty() ? "" : "; ") + note_ + "\n");
}

ProgressTicker::ProgressTicker(Progress& progress, std::function<void()> before) {
    if (progress.style() == ProgressStyle::none) return;
    thread_ = std::thread([this, &progress, before = std::move(before)]() {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!wake_.wait_for(lock, std::chrono::milliseconds(500), [this] { return done_; })) {
            if (before) before();
            progress.tick();
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

}  // namespace vi
