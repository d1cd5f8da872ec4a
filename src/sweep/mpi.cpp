#include "sweep/mpi.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <exception>
#include <fstream>
#include <mutex>
#include <string>
#include <stdexcept>
#include <thread>
#include <vector>

#include <unistd.h>

#include "model/cpu_budget.hpp"
#include "model/run_control.hpp"

// Protocol of collect(), on a communicator of its own:
//   other rank -> root: kPoint (a finished point, as bytes), kSignal (this rank was told to stop),
//                       then exactly one kDone after its last point;
//   root -> other rank: exactly one kStop, an int: 1 = stop starting points (sent as soon as the
//                       root stops), 0 = nothing more to do (sent after every kDone).
// Each side polls with MPI_Iprobe while its workers compute, so no rank blocks while another is
// blocked sending to it; the root's kStop goes out with MPI_Isend for the same reason.

namespace vi {
namespace {

enum Tag : int { kPoint = 1, kDone = 2, kSignal = 3, kStop = 4 };

// Ranks of `node` (the ranks on one machine) whose CPU affinity overlaps this rank's, this one
// included. Every rank sends its affinity bit set to all (a fixed number of 64-bit words: the
// longest set of the machine).
int count_ranks_sharing_cpus(MPI_Comm node) {
    int ranks = 1;
    int me = 0;
    MPI_Comm_size(node, &ranks);
    MPI_Comm_rank(node, &me);
    std::vector<std::uint64_t> mine = affinity_mask();
    int words = static_cast<int>(mine.size());
    int longest = 0;
    MPI_Allreduce(&words, &longest, 1, MPI_INT, MPI_MAX, node);
    if (longest == 0) return ranks;  // no rank knows its affinity: assume they all share the machine
    mine.resize(static_cast<std::size_t>(longest), 0);
    std::vector<std::uint64_t> all(static_cast<std::size_t>(longest) * static_cast<std::size_t>(ranks), 0);
    MPI_Allgather(mine.data(), longest, MPI_UINT64_T, all.data(), longest, MPI_UINT64_T, node);
    int sharing = 0;
    for (int r = 0; r < ranks; ++r) {
        const auto from = all.begin() + static_cast<std::ptrdiff_t>(r) * longest;
        const std::vector<std::uint64_t> theirs(from, from + longest);
        // A rank whose affinity is unknown (all zero) is counted as sharing.
        const bool unknown = std::all_of(theirs.begin(), theirs.end(), [](std::uint64_t w) { return w == 0; });
        if (r == me || unknown || masks_overlap(mine, theirs)) ++sharing;
    }
    return sharing;
}

constexpr auto kPoll = std::chrono::milliseconds(1);

// How long a stopped rank waits for MPI_Finalize before it ends without it (finalize_or_exit).
constexpr auto kStopFinalize = std::chrono::milliseconds(300);

// Whether this process's parent is an Open MPI launcher (mpirun, or the orted of a remote machine),
// read from /proc: only such a parent is nudged (nudge_launcher).
bool parent_is_open_mpi_launcher() {
    std::ifstream in("/proc/" + std::to_string(getppid()) + "/comm");
    std::string name;
    std::getline(in, name);
    return name == "mpirun" || name == "mpiexec" || name == "orterun" || name == "orted";
}

// Open MPI 4.1 ends a signalled job with SIGCONT to every rank, sleep(odls_base_sigkill_timeout =
// 1 s), SIGTERM, the same sleep, SIGKILL; a signal (a rank's exit raises SIGCHLD) cuts a sleep short,
// but only on the thread that sleeps. Ranks that all exit at one instant cut only the first sleep, so
// mpirun ended 1.3 s after its signal in 4 runs of 20 (0.3 s in the others). A stopped rank therefore
// sends its launcher a SIGCHLD every 10 ms while it still lives (a signal may land on another of
// mpirun's threads, hence the repeats): that cuts the first sleep. mpirun's SIGTERM then follows,
// but ending the rank at it left the second sleep to the one SIGCHLD of the rank's exit, which came
// before the sleep began or landed on another thread in about one run of a hundred (1.3 s again).
// So the stop signals are held while the rank nudges: the nudges go on, cut the second sleep too, and
// mpirun's SIGKILL ends the rank. At most 150 nudges (1.5 s); the caller then exits anyway. A
// spurious SIGCHLD only makes the launcher look for exited children.
void nudge_launcher() {
    // Only a launcher that is ending the job sleeps; one whose ranks were signalled directly is not.
    if (!launcher_stop() || !parent_is_open_mpi_launcher()) return;
    hold_stop_signals(true);
    for (int k = 0; k < 150; ++k) {
        if (kill(getppid(), SIGCHLD) != 0) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    hold_stop_signals(false);
}

std::vector<char> encode(const FinishedPoint& p) {
    const std::uint64_t index = p.index;
    const std::uint32_t status_size = static_cast<std::uint32_t>(p.status.size());
    std::vector<char> b(sizeof index + sizeof status_size + p.status.size() + p.row.size());
    char* at = b.data();
    std::memcpy(at, &index, sizeof index);
    at += sizeof index;
    std::memcpy(at, &status_size, sizeof status_size);
    at += sizeof status_size;
    std::memcpy(at, p.status.data(), p.status.size());
    at += p.status.size();
    std::memcpy(at, p.row.data(), p.row.size());
    return b;
}

FinishedPoint decode(const std::vector<char>& b) {
    std::uint64_t index = 0;
    std::uint32_t status_size = 0;
    if (b.size() < sizeof index + sizeof status_size) throw std::runtime_error("MPI: truncated sweep point message");
    std::memcpy(&index, b.data(), sizeof index);
    std::memcpy(&status_size, b.data() + sizeof index, sizeof status_size);
    const std::size_t head = sizeof index + sizeof status_size;
    if (b.size() < head + status_size) throw std::runtime_error("MPI: truncated sweep point message");
    FinishedPoint p;
    p.index = static_cast<std::size_t>(index);
    p.status.assign(b.data() + head, status_size);
    p.row.assign(b.data() + head + status_size, b.size() - head - status_size);
    return p;
}

// Points finished by this rank's workers, waiting for the MPI thread.
class PointQueue {
public:
    void push(const FinishedPoint& p) {
        const std::lock_guard<std::mutex> lock(mutex_);
        points_.push_back(p);
    }
    std::deque<FinishedPoint> take() {
        const std::lock_guard<std::mutex> lock(mutex_);
        std::deque<FinishedPoint> out;
        out.swap(points_);
        return out;
    }

private:
    std::mutex mutex_;
    std::deque<FinishedPoint> points_;
};

// Runs `local` on a thread of its own, its points into a queue.
class LocalWorker {
public:
    LocalWorker(const LocalRun& local, const std::atomic<bool>& stop)
        : thread_([this, &local, &stop]() {
              try {
                  local([this](const FinishedPoint& p) { queue_.push(p); }, stop);
              } catch (...) {
                  error_ = std::current_exception();
              }
              finished_.store(true);
          }) {}
    ~LocalWorker() {
        if (thread_.joinable()) thread_.join();
    }
    LocalWorker(const LocalWorker&) = delete;
    LocalWorker& operator=(const LocalWorker&) = delete;

    // True once `local` has returned; every point it emitted is then in the queue.
    [[nodiscard]] bool finished() const { return finished_.load(); }
    PointQueue& queue() { return queue_; }
    // Joins the thread and rethrows what `local` threw.
    void join() {
        if (thread_.joinable()) thread_.join();
        if (error_) std::rethrow_exception(error_);
    }

private:
    PointQueue queue_;
    std::atomic<bool> finished_{false};
    std::exception_ptr error_;
    std::thread thread_;  // last: starts once the members it uses exist
};

class MpiRanks final : public SweepRanks {
public:
    MpiRanks() {
        int provided = 0;
        if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
            throw std::runtime_error("MPI: MPI_Init_thread failed");
        }
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
        MPI_Comm_dup(MPI_COMM_WORLD, &points_comm_);
        MPI_Comm node = MPI_COMM_NULL;
        MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
        sharing_ = count_ranks_sharing_cpus(node);
        MPI_Comm_free(&node);
    }
    ~MpiRanks() override {
        MPI_Comm_free(&points_comm_);
        if (stop_flag().load()) {
            finalize_or_exit();
        } else {
            MPI_Finalize();
        }
    }
    MpiRanks(const MpiRanks&) = delete;
    MpiRanks& operator=(const MpiRanks&) = delete;

    [[nodiscard]] int rank() const override { return rank_; }
    [[nodiscard]] int size() const override { return size_; }
    [[nodiscard]] int ranks_sharing_cpus() const override { return sharing_; }

    int max_over_ranks(int value) override {
        int out = value;
        MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
        return out;
    }

    int broadcast(int value) override {
        MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
        return value;
    }

    std::vector<std::size_t> broadcast(std::vector<std::size_t> values) override {
        std::uint64_t n = values.size();
        MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
        std::vector<std::uint64_t> wire(values.begin(), values.end());
        wire.resize(static_cast<std::size_t>(n));
        // MPI counts are int: large lists go in pieces.
        constexpr std::size_t kPiece = 1u << 24;
        for (std::size_t at = 0; at < wire.size(); at += kPiece) {
            const int count = static_cast<int>(std::min(kPiece, wire.size() - at));
            MPI_Bcast(wire.data() + at, count, MPI_UINT64_T, 0, MPI_COMM_WORLD);
        }
        return {wire.begin(), wire.end()};
    }

    void collect(const LocalRun& local, const PointSink& sink, std::atomic<bool>& stop) override {
        if (rank_ == 0) {
            collect_on_root(local, sink, stop);
        } else {
            collect_on_other(local, stop);
        }
    }

private:
    // MPI_Finalize after a stop. When mpirun itself was signalled it tears the job down and no longer
    // answers MPI_Finalize's closing exchange, which then blocks until mpirun kills the rank (2 s
    // later, measured with Open MPI 4.1). Every finished point is already journaled, so the rank
    // waits at most kStopFinalize and then ends with the stop's exit code, 128 + the signal.
    static void finalize_or_exit() {
        std::fflush(nullptr);
        std::mutex m;
        std::condition_variable cv;
        bool done = false;
        std::thread guard([&] {
            std::unique_lock<std::mutex> lock(m);
            if (!cv.wait_for(lock, kStopFinalize, [&] { return done; })) {
                std::fflush(nullptr);
                nudge_launcher();
                std::_Exit(128 + (stop_signal() > 0 ? stop_signal() : SIGINT));
            }
        });
        MPI_Finalize();
        {
            const std::lock_guard<std::mutex> lock(m);
            done = true;
        }
        cv.notify_all();
        guard.join();
    }

    void collect_on_root(const LocalRun& local, const PointSink& sink, std::atomic<bool>& stop) {
        std::exception_ptr sink_error;
        auto deliver = [&](const FinishedPoint& p) {
            if (sink_error) return;
            try {
                sink(p);
            } catch (...) {
                // Keep the protocol going so that no rank hangs; stop everyone, report afterwards.
                sink_error = std::current_exception();
                stop.store(true);
            }
        };
        std::vector<int> stop_sent(static_cast<std::size_t>(size_), 0);
        std::vector<int> stop_value(static_cast<std::size_t>(size_), 0);
        std::vector<MPI_Request> requests;
        auto send_stops = [&](int value) {
            for (int r = 1; r < size_; ++r) {
                const auto k = static_cast<std::size_t>(r);
                if (stop_sent[k]) continue;
                stop_sent[k] = 1;
                stop_value[k] = value;
                requests.emplace_back();
                MPI_Isend(&stop_value[k], 1, MPI_INT, r, kStop, points_comm_, &requests.back());
            }
        };

        LocalWorker worker(local, stop);
        int running = size_ - 1;
        for (;;) {
            bool busy = false;
            if (stop.load()) send_stops(1);
            int flag = 0;
            MPI_Status st;
            MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, points_comm_, &flag, &st);
            if (flag) {
                busy = true;
                if (st.MPI_TAG == kPoint) {
                    int bytes = 0;
                    MPI_Get_count(&st, MPI_BYTE, &bytes);
                    std::vector<char> buf(static_cast<std::size_t>(bytes));
                    MPI_Recv(buf.data(), bytes, MPI_BYTE, st.MPI_SOURCE, kPoint, points_comm_, MPI_STATUS_IGNORE);
                    deliver(decode(buf));
                } else if (st.MPI_TAG == kDone) {
                    MPI_Recv(nullptr, 0, MPI_BYTE, st.MPI_SOURCE, kDone, points_comm_, MPI_STATUS_IGNORE);
                    --running;
                } else {
                    int value = 0;
                    MPI_Recv(&value, 1, MPI_INT, st.MPI_SOURCE, st.MPI_TAG, points_comm_, MPI_STATUS_IGNORE);
                    if (st.MPI_TAG == kSignal) stop.store(true);
                }
            }
            const bool local_finished = worker.finished();
            for (const FinishedPoint& p : worker.queue().take()) {
                busy = true;
                deliver(p);
            }
            if (local_finished && running == 0) break;
            if (!busy) std::this_thread::sleep_for(kPoll);
        }
        send_stops(0);
        MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
        worker.join();
        if (sink_error) std::rethrow_exception(sink_error);
    }

    void collect_on_other(const LocalRun& local, std::atomic<bool>& stop) {
        bool got_stop = false;
        bool signal_sent = false;
        auto send_points = [&](LocalWorker& w) {
            bool any = false;
            for (const FinishedPoint& p : w.queue().take()) {
                std::vector<char> buf = encode(p);
                MPI_Send(buf.data(), static_cast<int>(buf.size()), MPI_BYTE, 0, kPoint, points_comm_);
                any = true;
            }
            return any;
        };
        LocalWorker worker(local, stop);
        for (;;) {
            bool busy = false;
            int flag = 0;
            MPI_Iprobe(0, kStop, points_comm_, &flag, MPI_STATUS_IGNORE);
            if (flag) {
                int value = 0;
                MPI_Recv(&value, 1, MPI_INT, 0, kStop, points_comm_, MPI_STATUS_IGNORE);
                got_stop = true;
                if (value) stop.store(true);
                busy = true;
            }
            if (stop.load() && !got_stop && !signal_sent) {
                int one = 1;
                MPI_Send(&one, 1, MPI_INT, 0, kSignal, points_comm_);
                signal_sent = true;
            }
            const bool local_finished = worker.finished();
            busy = send_points(worker) || busy;
            if (local_finished) break;
            if (!busy) std::this_thread::sleep_for(kPoll);
        }
        send_points(worker);
        MPI_Send(nullptr, 0, MPI_BYTE, 0, kDone, points_comm_);
        if (!got_stop) {
            int value = 0;
            MPI_Recv(&value, 1, MPI_INT, 0, kStop, points_comm_, MPI_STATUS_IGNORE);
        }
        worker.join();
    }

    int rank_ = 0;
    int size_ = 1;
    int sharing_ = 1;
    MPI_Comm points_comm_ = MPI_COMM_NULL;
};

}  // namespace

std::unique_ptr<SweepRanks> start_mpi_ranks() { return std::make_unique<MpiRanks>(); }

}  // namespace vi
