#pragma once
// SweepRanks over MPI: the points of a sweep shared among the ranks of MPI_COMM_WORLD. Built only
// when CMake finds MPI (VI_HAVE_MPI); only the code that includes this header links MPI.

#include <memory>

#include "sweep/ranks.hpp"

namespace vi {

// Starts MPI (thread level "funneled": worker threads compute, only the calling thread talks MPI)
// and returns the ranks of MPI_COMM_WORLD; MPI is finalised when the object is destroyed. Throws
// std::runtime_error when MPI does not start.
std::unique_ptr<SweepRanks> start_mpi_ranks();

}  // namespace vi
