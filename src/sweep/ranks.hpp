#pragma once
// How the points of a sweep are shared among processes: one process, or MPI ranks (sweep_mpi.hpp).

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace vi {

// One finished point as it travels to the process that writes the files.
struct FinishedPoint {
    std::size_t index = 0;  // grid index
    std::string status;     // "ok" or "error: ..."
    std::string row;        // its CSV row (no newline)
};

// Receives finished points, one call at a time.
using PointSink = std::function<void(const FinishedPoint&)>;

// Computes this process's share of the points, passing each to `emit` as it finishes (emit may be
// called from worker threads, one call at a time) and starting no new point once `stop` is true.
using LocalRun = std::function<void(const PointSink& emit, const std::atomic<bool>& stop)>;

// The processes of a sweep. Rank 0 (the root) reads the journal and writes every file; the others
// only compute. Every collective call must be made by every rank in the same order.
class SweepRanks {
public:
    virtual ~SweepRanks() = default;
    [[nodiscard]] virtual int rank() const = 0;
    [[nodiscard]] virtual int size() const = 0;
    // Ranks on this machine whose allowed CPUs (affinity) overlap this rank's, this one included:
    // the ranks that share this rank's CPUs, for a default thread count. All ranks of the machine
    // when the launcher does not bind them; 1 when it gives each rank CPUs of its own.
    [[nodiscard]] virtual int ranks_sharing_cpus() const = 0;
    // Collective: the largest of every rank's value.
    virtual int max_over_ranks(int value) = 0;
    // Collective: the root's value, on every rank.
    virtual int broadcast(int value) = 0;
    // Collective: the root's list, on every rank.
    virtual std::vector<std::size_t> broadcast(std::vector<std::size_t> values) = 0;
    // Collective: runs `local` on every rank; on the root, calls `sink` for every rank's points as
    // they arrive, and returns once every rank has finished. `stop` is this rank's stop flag (set by
    // a signal); a stop on the root is passed on to every rank, a stop on another rank to the root.
    virtual void collect(const LocalRun& local, const PointSink& sink, std::atomic<bool>& stop) = 0;
};

// The single process of a sweep run without MPI.
class SingleProcess final : public SweepRanks {
public:
    [[nodiscard]] int rank() const override { return 0; }
    [[nodiscard]] int size() const override { return 1; }
    [[nodiscard]] int ranks_sharing_cpus() const override { return 1; }
    int max_over_ranks(int value) override { return value; }
    int broadcast(int value) override { return value; }
    std::vector<std::size_t> broadcast(std::vector<std::size_t> values) override { return values; }
    void collect(const LocalRun& local, const PointSink& sink, std::atomic<bool>& stop) override { local(sink, stop); }
};

// This rank's share of the points left to compute: every size-th entry of `todo`, from `rank`.
std::vector<std::size_t> share_of_rank(const std::vector<std::size_t>& todo, int rank, int size);

// True when this process was started by an MPI launcher (mpirun, mpiexec, srun): the launcher's
// environment variables are set (OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK).
bool launched_by_mpi();

// This process's rank as the launcher's environment tells it (0 when not launched by MPI).
int launcher_rank();

}  // namespace vi
