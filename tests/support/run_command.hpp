#pragma once
// Runs the vibroimpact command in a child process for command-line tests.

#include <string>
#include <vector>

namespace vi::test {

// What a finished command printed and returned.
struct CommandResult {
    int exit_code = -1;
    std::string out;  // standard output
    std::string err;  // standard error
};

// Runs the built vibroimpact executable with args (no shell involved) and waits for it.
CommandResult run_vibroimpact(const std::vector<std::string>& args);

// Path of a file under the source tree, e.g. source_path("examples/paper/cantilever.toml").
std::string source_path(const std::string& relative);

// A fresh empty directory under the system temp folder, unique per call.
std::string make_temp_dir();

}  // namespace vi::test
