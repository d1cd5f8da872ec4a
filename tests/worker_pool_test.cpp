// WorkerPool: every index of every round runs exactly once, on threads that last from round to
// round; a stop and an exception end a round, and the pool goes on with the next.

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "model/worker_pool.hpp"

namespace {

TEST(WorkerPool, EveryIndexOfEveryRoundRunsOnceOnThreadsThatLast) {
    for (int threads : {1, 2, 3}) {
        vi::WorkerPool pool(threads);
        EXPECT_EQ(pool.threads(), threads);
        std::mutex mutex;
        std::set<std::thread::id> ids;
        for (std::size_t round = 0; round < 50; ++round) {
            std::vector<std::atomic<int>> hits(round % 7);
            pool.run(hits.size(), [&](std::size_t i) {
                hits[i].fetch_add(1);
                const std::lock_guard<std::mutex> lock(mutex);
                ids.insert(std::this_thread::get_id());
            });
            for (const auto& h : hits) EXPECT_EQ(h.load(), 1) << "threads " << threads << ", round " << round;
        }
        EXPECT_LE(ids.size(), static_cast<std::size_t>(threads)) << "a thread was started for a round";
    }
}

TEST(WorkerPool, StopAndExceptionEndARoundAndThePoolGoesOn) {
    vi::WorkerPool pool(2);
    std::atomic<bool> stop{false};
    std::atomic<int> calls{0};
    pool.run(1000, [&](std::size_t i) {
        calls.fetch_add(1);
        if (i == 9) stop.store(true);
    }, &stop);
    EXPECT_GE(calls.load(), 10);
    EXPECT_LE(calls.load(), 11) << "indices started after the stop";
    EXPECT_THROW(pool.run(100, [](std::size_t i) {
        if (i == 3) throw std::runtime_error("bad");
    }), std::runtime_error);
    std::atomic<int> after{0};
    pool.run(20, [&](std::size_t) { after.fetch_add(1); });
    EXPECT_EQ(after.load(), 20);
}

}  // namespace
