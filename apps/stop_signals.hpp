#pragma once
// SIGINT and SIGTERM for every command: the first sets the stop flag that the solvers check
// (model/run_control.hpp), a second one ends the process at once; a commit section holds a second
// signal back while finished results go into place, so that no output is left half-replaced.

namespace vi::cli {

// Installs the handlers (SA_RESTART: a blocked system call carries on, it never fails with EINTR).
// The first SIGINT or SIGTERM calls request_stop(signal). A signal of either kind that comes
// kDuplicateWindow or later after it ends the process at once, by that signal; one sooner is the
// same stop delivered twice (`timeout` signals both the command and its process group) and counts
// once. A SIGINT ignored when the process started (a job started in the background by a script)
// stays ignored.
void install_stop_handlers();

// Two stop signals closer than this are one [ms].
inline constexpr long long kDuplicateWindowMs = 100;

// While it lives, a second signal does not end the process: the final files of a command that has
// finished computing are written completely (milliseconds). On leaving, a second signal that came
// during the section ends the process then, by that signal. Sections do not nest.
class CommitSection {
public:
    CommitSection();
    ~CommitSection();
    CommitSection(const CommitSection&) = delete;
    CommitSection& operator=(const CommitSection&) = delete;
};

}  // namespace vi::cli
