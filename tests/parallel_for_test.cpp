// parallel_for: every index runs exactly once whatever the thread count; stop and exceptions.

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "model/parallel_for.hpp"

namespace {

TEST(ParallelFor, EveryIndexRunsOnceForAnyThreadCount) {
    for (int threads : {1, 2, 3, 8}) {
        std::vector<std::atomic<int>> hits(257);
        const std::size_t ran = vi::parallel_for(hits.size(), threads, [&](std::size_t i) { hits[i].fetch_add(1); });
        EXPECT_EQ(ran, hits.size());
        for (const auto& h : hits) EXPECT_EQ(h.load(), 1) << "threads " << threads;
    }
}

TEST(ParallelFor, EmptyRangeRunsNothing) {
    EXPECT_EQ(vi::parallel_for(0, 4, [](std::size_t) { FAIL() << "body called for an empty range"; }), 0u);
}

TEST(ParallelFor, StopFlagEndsTheLoopEarly) {
    std::atomic<bool> stop{false};
    std::atomic<int> calls{0};
    const std::size_t ran = vi::parallel_for(
        1000, 1,
        [&](std::size_t i) {
            calls.fetch_add(1);
            if (i == 9) stop.store(true);
        },
        &stop);
    EXPECT_EQ(ran, 10u);
    EXPECT_EQ(calls.load(), 10);
}

TEST(ParallelFor, ExceptionIsRethrownAfterJoin) {
    EXPECT_THROW(vi::parallel_for(100, 2,
                                  [](std::size_t i) {
                                      if (i == 50) throw std::runtime_error("point 50");
                                  }),
                 std::runtime_error);
}

TEST(ParallelFor, ThreadCountDefaultsToTheMachine) {
    EXPECT_EQ(vi::resolve_thread_count(3), 3);
    EXPECT_GE(vi::resolve_thread_count(0), 1);
}

}  // namespace
