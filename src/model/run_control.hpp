#pragma once
// Run control: the process-wide stop flag that SIGINT/SIGTERM set, and a per-thread wall-clock limit
// (a sweep point's --point-timeout), both checked inside the solvers' loops by check_run().

#include <atomic>
#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>

namespace vi {

// Thrown by check_run() once a stop was requested (a signal, or a sweep that stops its workers):
// the work is abandoned, nothing of it is a result. Deliberately not a std::exception: the places
// that turn a failed computation into a reported result (a sweep point's status, a gap in a paper
// figure) catch std::exception, and a stop must pass through them to the command.
class StopRequested {
public:
    explicit StopRequested(int signal) : signal_(signal) {}
    [[nodiscard]] int signal() const { return signal_; }  // the signal's number, or 0
private:
    int signal_;
};

// Thrown by check_run() when this thread's wall-clock limit (ScopedTimeLimit) has passed; the
// message names the limit and the setting that raises it, and what the work was doing when a
// ProgressNote says.
class TimeLimitReached : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Thrown when a bound on the work of one run (events, search steps, iterations) is reached; the
// message says what, where, at which time and which setting raises the bound.
class WorkLimitReached : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The process-wide stop flag. Async-signal-safe to set (lock-free atomics only).
std::atomic<bool>& stop_flag();
// Sets the flag and remembers the signal (0: not a signal); safe inside a signal handler.
void request_stop(int signal) noexcept;
// The signal that requested the stop, or 0.
int stop_signal() noexcept;
// Marks the stop as the launcher's (mpirun ending the job: it will go on to SIGTERM and SIGKILL
// the process); safe inside a signal handler. launcher_stop() tells.
void note_launcher_stop() noexcept;
bool launcher_stop() noexcept;
// While a stopped rank nudges its launcher (sweep/mpi.cpp), a further stop signal must not end the
// process: the launcher's SIGTERM comes just before it sleeps, and the nudges that go on are what cut
// that sleep. The handlers of the stop signals ignore them while held; safe inside a signal handler.
void hold_stop_signals(bool hold) noexcept;
bool stop_signals_held() noexcept;
// Clears the flag and the signal (start of a command, or of a test).
void clear_stop() noexcept;

// A wall-clock limit for the work done on this thread while the object lives [s]; 0 or less: none.
// `setting` names what sets it, for the message ("--point-timeout"). Limits do not nest: the inner
// one replaces the outer one until it ends.
class ScopedTimeLimit {
public:
    ScopedTimeLimit(double seconds, std::string setting);
    ~ScopedTimeLimit();
    ScopedTimeLimit(const ScopedTimeLimit&) = delete;
    ScopedTimeLimit& operator=(const ScopedTimeLimit&) = delete;

private:
    double previous_deadline_;
    double previous_seconds_;
    std::string previous_setting_;
};

// While it lives, a time limit reached on this thread says what the work was doing: describe()'s
// text is added to the TimeLimitReached message ("the exact solver had reached t = ..."). It is
// called only then, on this thread, from inside the work (check_run), so it may read the work's
// state as it is at that moment and compute what it reports; the work pays nothing until then.
// Notes nest: the inner one speaks while it lives.
class ProgressNote {
public:
    explicit ProgressNote(std::function<std::string()> describe);
    ~ProgressNote();
    ProgressNote(const ProgressNote&) = delete;
    ProgressNote& operator=(const ProgressNote&) = delete;

private:
    std::function<std::string()> describe_;
    const std::function<std::string()>* previous_;
};

// Seconds since this thread's current time limit began, or 0 without one.
double time_limit_elapsed();

// Wall-clock seconds since t0 (steady clock), for the time figures that results report.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Throws StopRequested when a stop was requested, TimeLimitReached when this thread's time limit has
// passed. Cheap (an atomic load; the clock only when a limit is set): call it in every solver loop.
void check_run();

}  // namespace vi
