#pragma once
// WorkerPool: worker threads kept for many rounds of parallel work (the batches of an
// optimisation), so that what a thread keeps from one run to the next (the eigen solver's memo of
// its last modes) lasts, and no thread is started per round.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace vi {

class WorkerPool {
public:
    // resolve_thread_count(threads) threads in all: the caller of run() and that many less one
    // workers.
    explicit WorkerPool(int threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    [[nodiscard]] int threads() const { return static_cast<int>(workers_.size()) + 1; }

    // Calls body(i) once for every i in [0, count) on the pool's threads and the caller's, handing
    // the indices out in increasing order, and returns when all have run. When *stop becomes true no
    // further index starts. body must not throw: an exception escaping it stops the round and is
    // rethrown here once every thread is done with it. One round at a time.
    void run(std::size_t count, const std::function<void(std::size_t)>& body, const std::atomic<bool>* stop = nullptr);

private:
    void work();
    void loop();

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::size_t generation_ = 0;  // rounds started
    std::size_t busy_ = 0;        // workers still in the current round
    bool shutdown_ = false;
    // The current round.
    const std::function<void(std::size_t)>* body_ = nullptr;
    std::size_t count_ = 0;
    const std::atomic<bool>* stop_ = nullptr;
    std::atomic<std::size_t> next_{0};
    std::atomic<bool> failed_{false};
    std::exception_ptr error_;
};

}  // namespace vi
