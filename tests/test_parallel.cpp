// core/parallel.cpp: every index exactly once on any worker count, the calling thread alone for one worker,
// and an exception carried back to the caller with the hand-out stopped.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/parallel.hpp"

using namespace t2imu;

TEST(ParallelFor, RunsEveryIndexExactlyOnce) {
    for (int threads : {0, 1, 3, 64}) {
        std::vector<std::atomic<int>> hits(1000);
        parallel_for(hits.size(), threads, [&](size_t i) { ++hits[i]; });
        for (size_t i = 0; i < hits.size(); ++i)
            ASSERT_EQ(hits[i].load(), 1) << "index " << i << ", " << threads << " threads";
    }
    parallel_for(0, 4, [](size_t) { FAIL() << "no index to run"; });
}

TEST(ParallelFor, OneWorkerRunsInOrderOnTheCallingThread) {
    std::vector<size_t> order;
    const std::thread::id caller = std::this_thread::get_id();
    parallel_for(5, 1, [&](size_t i) {
        EXPECT_EQ(std::this_thread::get_id(), caller);
        order.push_back(i);
    });
    EXPECT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 4}));
}

TEST(ParallelFor, RethrowsTheFirstErrorAndStopsHandingOutWork) {
    std::atomic<int> ran{0};
    std::atomic<bool> thrown{false};
    EXPECT_THROW(parallel_for(100000, 2,
                              [&](size_t i) {
                                  ++ran;
                                  if (i == 10) {
                                      thrown = true;
                                      throw std::runtime_error("index 10");
                                  }
                                  // After the throw every index takes 0.1 ms, so the other worker could finish
                                  // the rest only if the failing one stalled for 10 s between throw and catch.
                                  if (thrown) std::this_thread::sleep_for(std::chrono::microseconds(100));
                              }),
                 std::runtime_error);
    EXPECT_LT(ran.load(), 100000);  // the remaining indices were not handed out
    try {
        parallel_for(3, 1, [](size_t i) {
            if (i == 1) throw std::runtime_error("index 1");
        });
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "index 1");
    }
}
