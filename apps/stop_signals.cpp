#include "stop_signals.hpp"

#include <signal.h>
#include <time.h>

#include <atomic>
#include <cstdlib>

#include "model/run_control.hpp"

namespace vi::cli {
namespace {

constexpr int kStopSignals[] = {SIGINT, SIGTERM};

// When the first stop signal came [ns of CLOCK_MONOTONIC], 0 before; whether a commit section runs;
// a second signal held back by it (0: none).
std::atomic<long long> g_first_ns{0};
std::atomic<bool> g_in_commit{false};
std::atomic<int> g_deferred{0};
static_assert(std::atomic<long long>::is_always_lock_free && std::atomic<bool>::is_always_lock_free &&
                  std::atomic<int>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");

long long now_ns() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<long long>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

// Ends the process by `signal`: its default action, delivered once the handler (which blocks it)
// returns, or at once outside a handler.
void end_by(int signal) {
    struct sigaction sa {};
    sa.sa_handler = SIG_DFL;
    sigemptyset(&sa.sa_mask);
    sigaction(signal, &sa, nullptr);
    raise(signal);
}

// Only async-signal-safe calls: atomics, clock_gettime, sigaction, raise.
extern "C" void on_stop_signal(int signal) {
    const long long now = now_ns();
    long long first = 0;
    if (g_first_ns.compare_exchange_strong(first, now)) {
        vi::request_stop(signal);
        return;
    }
    if (now - first < kDuplicateWindowMs * 1000000LL) return;  // the same stop, delivered twice
    if (vi::stop_signals_held()) return;  // a rank nudging mpirun: mpirun's SIGTERM, its SIGKILL follows
    if (g_in_commit.load()) {
        g_deferred.store(signal);
        return;
    }
    end_by(signal);
}

// mpirun's first step in ending a job (Open MPI 4.1, on its own SIGINT/SIGTERM or an aborting
// rank) is a SIGCONT to every rank; it then waits odls_base_sigkill_timeout (1 s) before the SIGTERM.
// It forwards no job control to the ranks (unless orte_forward_job_control is set), so under mpirun a
// SIGCONT means the job is ending: taken as that SIGTERM, the ranks stop a second sooner. It only
// ever starts a stop: after a stop already under way (a rank signalled directly, whose exit makes
// mpirun end the job) it must not count as the second signal that ends the process at once.
extern "C" void on_mpirun_continue(int) {
    long long first = 0;
    if (g_first_ns.compare_exchange_strong(first, now_ns())) {
        vi::note_launcher_stop();
        vi::request_stop(SIGTERM);
    }
}

bool under_mpirun() { return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr; }

}  // namespace

// Installs fn for signal with the stop signals and SIGCONT blocked while it runs: no handler runs
// inside another, so the first-signal bookkeeping stays consistent.
static void handle(int signal, void (*fn)(int)) {
    struct sigaction sa {};
    sa.sa_handler = fn;
    sigemptyset(&sa.sa_mask);
    for (const int m : kStopSignals) sigaddset(&sa.sa_mask, m);
    sigaddset(&sa.sa_mask, SIGCONT);
    sa.sa_flags = SA_RESTART;
    sigaction(signal, &sa, nullptr);
}

void install_stop_handlers() {
    for (const int s : kStopSignals) {
        struct sigaction old {};
        sigaction(s, nullptr, &old);
        if (s == SIGINT && (old.sa_flags & SA_SIGINFO) == 0 && old.sa_handler == SIG_IGN) continue;
        handle(s, on_stop_signal);
    }
    if (under_mpirun()) handle(SIGCONT, on_mpirun_continue);
}

CommitSection::CommitSection() {
    g_deferred.store(0);
    g_in_commit.store(true);
}

CommitSection::~CommitSection() {
    g_in_commit.store(false);
    if (const int signal = g_deferred.exchange(0); signal != 0) end_by(signal);
}

}  // namespace vi::cli
