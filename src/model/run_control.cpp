#include "model/run_control.hpp"

#include <chrono>
#include <cstdio>

namespace vi {
namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
std::atomic<bool> g_launcher{false};
std::atomic<bool> g_holding{false};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");

double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// This thread's limit: an absolute steady-clock time [s], 0 for none.
thread_local double t_deadline = 0.0;
thread_local double t_seconds = 0.0;
thread_local std::string t_setting;
// The innermost ProgressNote of this thread, or null.
thread_local const std::function<std::string()>* t_note = nullptr;

// What the innermost note says, or "" (a note that fails to say is left out: the timeout matters more).
std::string progress_text() {
    if (t_note == nullptr || !*t_note) return "";
    try {
        return (*t_note)();
    } catch (...) {
        return "";
    }
}

}  // namespace

std::atomic<bool>& stop_flag() { return g_stop; }

void request_stop(int signal) noexcept {
    g_signal.store(signal);
    g_stop.store(true);
}

int stop_signal() noexcept { return g_signal.load(); }

void note_launcher_stop() noexcept { g_launcher.store(true); }
bool launcher_stop() noexcept { return g_launcher.load(); }
void hold_stop_signals(bool hold) noexcept { g_holding.store(hold); }
bool stop_signals_held() noexcept { return g_holding.load(); }

void clear_stop() noexcept {
    g_stop.store(false);
    g_signal.store(0);
    g_launcher.store(false);
    g_holding.store(false);
}

ScopedTimeLimit::ScopedTimeLimit(double seconds, std::string setting)
    : previous_deadline_(t_deadline), previous_seconds_(t_seconds), previous_setting_(std::move(t_setting)) {
    t_seconds = seconds > 0.0 ? seconds : 0.0;
    t_deadline = seconds > 0.0 ? now_s() + seconds : 0.0;
    t_setting = std::move(setting);
}

ScopedTimeLimit::~ScopedTimeLimit() {
    t_deadline = previous_deadline_;
    t_seconds = previous_seconds_;
    t_setting = std::move(previous_setting_);
}

ProgressNote::ProgressNote(std::function<std::string()> describe) : describe_(std::move(describe)), previous_(t_note) {
    t_note = &describe_;
}

ProgressNote::~ProgressNote() { t_note = previous_; }

double time_limit_elapsed() { return t_deadline > 0.0 ? now_s() - (t_deadline - t_seconds) : 0.0; }

void check_run() {
    if (g_stop.load(std::memory_order_relaxed)) throw StopRequested(g_signal.load());
    if (t_deadline > 0.0 && now_s() > t_deadline) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%g", t_seconds);
        const std::string doing = progress_text();
        throw TimeLimitReached("timeout: more than " + std::string(buf) + " s of wall time (raise " + t_setting + ")" +
                               (doing.empty() ? "" : "; " + doing));
    }
}

}  // namespace vi
