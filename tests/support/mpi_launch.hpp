#pragma once
// Launching the vibroimpact command under `mpirun -n 2` for command-line tests, and why it cannot
// run here when it cannot.

#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace vi::test {

// mpirun on PATH, or empty.
std::string find_mpirun();

// Why the MPI parts of a test cannot run here (no MPI in the build, no mpirun), or empty.
std::string mpi_unavailable();

// The command line `mpirun -n <ranks> vibroimpact args...` as this machine allows (root needs
// --allow-run-as-root; --oversubscribe lets 2 ranks run on fewer cores).
std::vector<std::string> mpi_argv(const std::vector<std::string>& args, int ranks = 2);

// Extra environment for an MPI run: under the sanitizers, LeakSanitizer is told about the
// allocations OpenMPI keeps until exit and needs full stacks to see them (tests/lsan-openmpi.supp);
// the variables do nothing in other builds.
std::vector<std::string> mpi_env();

// Runs `mpirun -n 2 vibroimpact args...` and waits for it (at most limit_s; a hang kills every rank).
CommandResult run_mpi(const std::vector<std::string>& args, double limit_s = kHangLimitSeconds);

}  // namespace vi::test
