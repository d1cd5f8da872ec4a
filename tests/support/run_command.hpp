#pragma once
// Runs the vibroimpact command (or another program) in a child process for command-line tests.

#include <sys/types.h>

#include <string>
#include <vector>

namespace vi::test {

// What a finished command printed and returned.
struct CommandResult {
    int exit_code = -1;
    std::string out;  // standard output
    std::string err;  // standard error
    bool timed_out = false;  // killed (SIGKILL) at its time limit; exit_code is then 128 + 9
    double seconds = 0.0;    // wall-clock time until it ended or was killed [s]
};

// Runs the built vibroimpact executable with args (no shell involved) and waits for it.
CommandResult run_vibroimpact(const std::vector<std::string>& args);

// Runs the built vibroimpact executable with args, killing it (SIGKILL) when it has not ended after
// limit_seconds of wall-clock time: a hang is reported as timed_out instead of hanging the test.
CommandResult run_vibroimpact_limited(const std::vector<std::string>& args, double limit_seconds);

// Runs argv[0] (searched on PATH when it has no slash) with the rest of argv and waits for it;
// env holds extra "NAME=value" entries for the child's environment.
CommandResult run_program(const std::vector<std::string>& argv, const std::vector<std::string>& env = {});

// A program started in the background, its output into files; wait() reaps it.
class ChildProcess {
public:
    ChildProcess(const std::vector<std::string>& argv, const std::vector<std::string>& env = {});
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;
    [[nodiscard]] pid_t pid() const { return pid_; }
    // Waits for the end: the exit code, or 128 + the signal that ended it.
    CommandResult wait();

private:
    std::string dir_;
    pid_t pid_ = -1;
    bool reaped_ = false;
};

// Path of the built vibroimpact executable.
std::string vibroimpact_path();

// Path of a file under the source tree, e.g. source_path("examples/paper/cantilever.toml").
std::string source_path(const std::string& relative);

// A fresh empty directory under the system temp folder, unique per call.
std::string make_temp_dir();

}  // namespace vi::test
