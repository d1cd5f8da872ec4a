#pragma once
// Subcommands of the vibroimpact command: each registers its options and returns an exit code.

#include <CLI/CLI.hpp>
#include <functional>

namespace vi::cli {

// Exit codes (POSIX habit): success, failure of the computation, bad input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;
// A command stopped by a signal exits 128 + its number (130 for SIGINT, 143 for SIGTERM): the shell's habit.
inline constexpr int kExitStoppedBase = 128;

// What --version prints, and what reports name as their author.
inline constexpr const char* kVersionText = "vibroimpact 0.1.0";

// A subcommand's body, run after parsing; returns the exit code.
using CommandBody = std::function<int()>;

CommandBody add_modes_command(CLI::App& app);
CommandBody add_support_scan_command(CLI::App& app);
CommandBody add_simulate_command(CLI::App& app);
CommandBody add_cycles_command(CLI::App& app);
CommandBody add_validate_command(CLI::App& app);
CommandBody add_sweep_command(CLI::App& app);
CommandBody add_paper_command(CLI::App& app);
CommandBody add_pullin_command(CLI::App& app);
CommandBody add_switch_report_command(CLI::App& app);
CommandBody add_optimize_command(CLI::App& app);
CommandBody add_fit_command(CLI::App& app);
CommandBody add_new_command(CLI::App& app);
CommandBody add_stiction_command(CLI::App& app);
CommandBody add_air_q_command(CLI::App& app);
CommandBody add_uq_command(CLI::App& app);
CommandBody add_plot_command(CLI::App& app);
CommandBody add_man_command(CLI::App& app);
CommandBody add_completion_command(CLI::App& app);

}  // namespace vi::cli
