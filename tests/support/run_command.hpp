#pragma once
// Runs the vibroimpact command (or another program) in a child process for command-line tests.

#include <sys/types.h>

#include <functional>
#include <string>
#include <vector>

namespace vi::test {

// What a finished command printed and returned.
struct CommandResult {
    int exit_code = -1;         // the exit status, or 128 + the signal that ended the process
    int term_signal = 0;        // the signal that ended the process, or 0 when it exited
    std::string out;  // standard output
    std::string err;  // standard error
    bool hung = false;          // outlived its limit and was killed (SIGKILL): a hang
    double seconds = 0.0;       // wall time from start to end [s]
    double cpu_seconds = 0.0;   // CPU time of the process, user and system, its reaped children included [s]
    double after_signal = -1.0; // wall time from the first ChildProcess::signal() to the end [s], or -1
};

// How long a child may run before a test counts it as hung [s]: generous, far above any command of
// the suite, and below CTest's per-test TIMEOUT (600 s) so that the test itself reports the hang.
inline constexpr double kHangLimitSeconds = 300.0;

// How soon after a signal a stopped command must have ended [s]. The requirement is 1 s; the bound
// is generous because the machine may be shared (the tests print the measured figure). Under the
// sanitizers everything runs several times slower, so there it only catches a stop that does not
// work at all.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
inline constexpr double kStopBound = 15.0;
#else
inline constexpr double kStopBound = 3.0;
#endif

// Runs the built vibroimpact executable with args (no shell involved) and waits for it, at most
// limit_s seconds (then it is killed and the result says hung).
CommandResult run_vibroimpact(const std::vector<std::string>& args, double limit_s = kHangLimitSeconds);

// Runs argv[0] (searched on PATH when it has no slash) with the rest of argv and waits for it, at
// most limit_s seconds; env holds extra "NAME=value" entries for the child's environment.
CommandResult run_program(const std::vector<std::string>& argv, const std::vector<std::string>& env = {},
                          double limit_s = kHangLimitSeconds);

// A program started in the background, its output into files; wait() reaps it. With
// `own_group`, the child leads a process group of its own (signal_group() then reaches it and every
// process it starts, as a terminal's Ctrl-C does).
class ChildProcess {
public:
    ChildProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env = {},
                 bool own_group = false);
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;
    [[nodiscard]] pid_t pid() const { return pid_; }
    // The file the child's standard error goes to (readable while it runs).
    [[nodiscard]] std::string stderr_path() const { return dir_ + "/stderr"; }
    // Seconds since the child started.
    [[nodiscard]] double seconds() const;
    // CPU seconds the child has used so far, user and system (its reaped children included).
    [[nodiscard]] double cpu_seconds() const;
    // Sends sig to the child (the first call starts the clock of CommandResult::after_signal).
    void signal(int sig);
    // Sends sig to the child's process group (needs own_group).
    void signal_group(int sig);
    // Sends sig to every process the child started (its direct children: mpirun's ranks) and
    // returns how many there were.
    int signal_children(int sig);
    // True while the child has not ended (reaps it when it has; wait() then reports it).
    [[nodiscard]] bool running();
    // Waits for the end, at most limit_s seconds from now (then SIGKILL, and the result says hung):
    // the exit code, or 128 + the signal that ended it.
    CommandResult wait(double limit_s = kHangLimitSeconds);

private:
    std::string dir_;
    pid_t pid_ = -1;
    bool own_group_ = false;
    bool reaped_ = false;
    int status_ = 0;          // wait status, once reaped
    double cpu_ = 0.0;        // CPU seconds, once reaped
    double started_ = 0.0;    // steady clock [s]
    double signalled_ = -1.0; // steady clock of the first signal [s], or -1
    double ended_ = 0.0;      // steady clock when reaped [s]
};

// Runs argv on a pseudo-terminal (stdin, stdout and stderr all the terminal, as in an interactive
// shell) and returns everything it wrote there in `out`; at most limit_s seconds (then hung).
CommandResult run_on_terminal(const std::vector<std::string>& argv, double limit_s = kHangLimitSeconds);

// Polls `ready` every few milliseconds until it returns true or limit_s seconds pass; returns its
// last answer.
bool wait_until(const std::function<bool()>& ready, double limit_s);

// The full path of program `name` on PATH, or empty when it is not there.
std::string find_on_path(const std::string& name);

// Path of the built vibroimpact executable.
std::string vibroimpact_path();

// Path of a file under the source tree, e.g. source_path("examples/paper/cantilever.toml").
std::string source_path(const std::string& relative);

// A fresh empty directory under the system temp folder, unique per call.
std::string make_temp_dir();

}  // namespace vi::test
