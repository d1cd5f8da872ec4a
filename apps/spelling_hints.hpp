#pragma once
// "Did you mean ...?" for a command line CLI11 refused: a misspelled subcommand or option.

#include <CLI/CLI.hpp>
#include <string>

namespace vi::cli {

// The hint for argv after a parse error: "; 'simulat' is unknown: did you mean 'simulate'?" when the first word is no
// subcommand but near one, or when an option "--name" the chosen subcommand does not have is near
// one it has; "; 'xyzzy' is not a command" for a first word near no subcommand; empty otherwise.
std::string spelling_hint(const CLI::App& app, int argc, const char* const* argv);

}  // namespace vi::cli
