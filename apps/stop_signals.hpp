#pragma once
// SIGINT and SIGTERM for every command: the first sets the stop flag that the solvers check
// (model/run_control.hpp), a second one ends the process at once; a commit section holds a second
// signal back while finished results go into place, so that no output is left half-replaced.

namespace vi::cli {

// Installs the handlers. The first SIGINT or SIGTERM calls request_stop(signal) and puts both
// signals back to their default action, so that the next one of either ends the process. A SIGINT
// ignored when the process started (a job started in the background by a script) stays ignored.
void install_stop_handlers();

// While it lives, SIGINT and SIGTERM only set the stop flag: the final files of a command that has
// finished computing are written completely (milliseconds). On leaving, a signal that came during
// the section and would have ended the process (a second signal) ends it then, with that signal.
class CommitSection {
public:
    CommitSection();
    ~CommitSection();
    CommitSection(const CommitSection&) = delete;
    CommitSection& operator=(const CommitSection&) = delete;
};

}  // namespace vi::cli
