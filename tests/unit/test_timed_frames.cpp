// The timing loop's warm-up: frames before the clocks settle are thrown away, by count and, on a GPU, by time.
#include "timing/repeated_timing.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace shadowlab {
namespace {

TEST(TimedFrames, WarmUpThrowsAwayAtLeastTheFramesAndTheTimeItIsGiven) {
    // A "GPU" that runs slow (10 ms) for its first 150 ms, then fast (1 ms): the first sweep point on the lent H100
    // paid exactly this. The median must be the settled time.
    const auto start = std::chrono::steady_clock::now();
    int calls = 0;
    const RepeatedTiming timing = timeRepeated(
        5,
        [&](std::vector<double>& ms) -> std::string {
            ++calls;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            const double elapsed =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            ms = {elapsed < 150.0 ? 10.0 : 1.0};
            return "";
        },
        200.0);
    ASSERT_TRUE(timing.error.empty());
    ASSERT_EQ(timing.medianMs.size(), 1u);
    EXPECT_DOUBLE_EQ(timing.medianMs[0], 1.0);
    EXPECT_GT(timing.warmUpRuns, kWarmUpFrames);
    EXPECT_EQ(calls, timing.warmUpRuns + 5);
}

TEST(TimedFrames, WithoutAWarmUpTimeOnlyTheFixedFramesAreThrownAway) {
    int calls = 0;
    const RepeatedTiming timing = timeRepeated(4, [&](std::vector<double>& ms) -> std::string {
        ms = {double(++calls)};
        return "";
    });
    EXPECT_EQ(timing.warmUpRuns, kWarmUpFrames);
    EXPECT_EQ(calls, kWarmUpFrames + 4);
    // Runs kWarmUpFrames+1 .. kWarmUpFrames+4 are timed: their median is the mean of the middle two.
    EXPECT_DOUBLE_EQ(timing.medianMs[0], kWarmUpFrames + 2.5);
    EXPECT_DOUBLE_EQ(timing.minMs[0], kWarmUpFrames + 1.0);
}

TEST(TimedFrames, AnErrorStopsTheLoopAndIsReturned) {
    int calls = 0;
    const RepeatedTiming timing = timeRepeated(
        10, [&](std::vector<double>&) -> std::string { return ++calls == 2 ? "lost the context" : ""; }, 1e6);
    EXPECT_EQ(timing.error, "lost the context");
    EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace shadowlab
