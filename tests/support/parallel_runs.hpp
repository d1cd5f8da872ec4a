#pragma once
// Runs many short commands a few at a time in child processes, each with its own wall-clock limit,
// for the fuzz tests: the machine's cores work on several mutants at once.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace vi::test {

// How long one run may go on before it is killed as a hang: its CPU time (user and system, its
// reaped children included), which other work on the machine does not stretch, and a wall-clock
// backstop for a run that waits without computing.
struct RunLimits {
    double cpu_s = 20.0;
    double wall_s = 120.0;
};

// Runs count commands, at most `parallel` at a time: start(i) prepares run i and returns its argv
// (empty: nothing to run, i is skipped); done(i, result) is called as each ends, in the order they
// end. A run past either limit is killed with its process group (result.hung). Before each start,
// keep_going() may end the series (no more runs start; those under way finish).
void run_in_parallel(std::size_t count, std::size_t parallel, const RunLimits& limits,
                     const std::function<std::vector<std::string>(std::size_t)>& start,
                     const std::function<void(std::size_t, const CommandResult&)>& done,
                     const std::function<bool()>& keep_going);

}  // namespace vi::test
