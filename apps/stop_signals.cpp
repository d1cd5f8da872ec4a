#include "stop_signals.hpp"

#include <signal.h>

#include <atomic>

#include "model/run_control.hpp"

namespace vi::cli {
namespace {

constexpr int kStopSignals[] = {SIGINT, SIGTERM};

// Signals that arrived during a commit section, and the last of them.
std::atomic<int> g_commit_count{0};
std::atomic<int> g_commit_last{0};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

void set_action(int signal, void (*handler)(int), int flags, struct sigaction* old = nullptr) {
    struct sigaction sa {};
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    // Neither handler runs inside the other: the disposition changes stay consistent.
    for (const int s : kStopSignals) sigaddset(&sa.sa_mask, s);
    sa.sa_flags = flags;
    sigaction(signal, &sa, old);
}

// Only async-signal-safe calls: atomics and sigaction.
extern "C" void on_stop_signal(int signal) {
    vi::request_stop(signal);
    for (const int s : kStopSignals) set_action(s, SIG_DFL, 0);
}

extern "C" void on_signal_in_commit(int signal) {
    g_commit_last.store(signal);
    g_commit_count.fetch_add(1);
}

bool is_stop_handler(const struct sigaction& sa) {
    return (sa.sa_flags & SA_SIGINFO) == 0 && sa.sa_handler == on_stop_signal;
}

}  // namespace

void install_stop_handlers() {
    for (const int s : kStopSignals) {
        struct sigaction old {};
        sigaction(s, nullptr, &old);
        if (s == SIGINT && (old.sa_flags & SA_SIGINFO) == 0 && old.sa_handler == SIG_IGN) continue;
        set_action(s, on_stop_signal, SA_RESETHAND);
    }
}

namespace {
struct sigaction g_saved[2];
}  // namespace

CommitSection::CommitSection() {
    g_commit_count.store(0);
    g_commit_last.store(0);
    for (int k = 0; k < 2; ++k) {
        sigaction(kStopSignals[k], nullptr, &g_saved[k]);
        // An ignored signal stays ignored.
        if ((g_saved[k].sa_flags & SA_SIGINFO) == 0 && g_saved[k].sa_handler == SIG_IGN) continue;
        set_action(kStopSignals[k], on_signal_in_commit, 0);
    }
}

CommitSection::~CommitSection() {
    // Was the stop handler still in place, i.e. had no stop signal come before the section?
    const bool armed = is_stop_handler(g_saved[0]) || is_stop_handler(g_saved[1]);
    for (int k = 0; k < 2; ++k) sigaction(kStopSignals[k], &g_saved[k], nullptr);
    const int count = g_commit_count.load();
    if (count == 0) return;
    const int last = g_commit_last.load();
    // What the handlers would have done, in order: the first signal (if armed) stops, the next ends.
    if (armed) {
        vi::request_stop(last);
        for (const int s : kStopSignals) set_action(s, SIG_DFL, 0);
        if (count == 1) return;
    }
    raise(last);
}

}  // namespace vi::cli
