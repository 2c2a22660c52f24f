// The CLI's progress line (app/cli/progress.h): its text, the time left it estimates, and when it is drawn at all.
#include "cli/progress.h"

#include <gtest/gtest.h>

using namespace shadowlab::cli;

TEST(CliProgress, ClockTextIsMinutesAndSecondsThenHours) {
    EXPECT_EQ(clockText(0.0), "00:00");
    EXPECT_EQ(clockText(31.4), "00:31");
    EXPECT_EQ(clockText(70.0), "01:10");
    EXPECT_EQ(clockText(3723.0), "1:02:03");
    EXPECT_EQ(clockText(-5.0), "00:00");
}

TEST(CliProgress, TheLineCountsUnitsAndEstimatesTheTimeLeftFromTheFinishedShare) {
    // 12 of 40 points in 31 s: 31 x 28 / 12 = 72.3 s left.
    EXPECT_EQ(progressLine({"sweep", 12, 40, "points", 0.0, 31.0, ""}), "sweep 12/40 points, 00:31 elapsed, ~01:12 left");
    // Half of the 13th point is finished too: 12.5 / 40 done, 31 x 27.5 / 12.5 = 68.2 s left.
    EXPECT_EQ(progressLine({"sweep", 12, 40, "points", 0.5, 31.0, "timing pcf"}),
              "sweep 12/40 points, 00:31 elapsed, ~01:08 left (timing pcf)");
    // Nothing finished yet: no estimate rather than a made-up one.
    EXPECT_EQ(progressLine({"check", 0, 3, "cases", 0.0, 2.0, ""}), "check 0/3 cases, 00:02 elapsed, estimating time left");
    // All done: nothing left, and a stale partial is not counted past the end.
    EXPECT_EQ(progressLine({"tune", 2, 2, "lights", 0.7, 65.0, ""}), "tune 2/2 lights, 01:05 elapsed, ~00:00 left");
}

TEST(CliProgress, WorkWithoutACountShowsItsPercentage) {
    // 25 % in 3 s: 9 s left.
    EXPECT_EQ(progressLine({"measure", 0, 0, "", 0.25, 3.0, "tracing shadow rays"}),
              "measure 25 %, 00:03 elapsed, ~00:09 left (tracing shadow rays)");
}

TEST(CliProgress, DrawnOnlyOnATerminalOutsideCi) {
    EXPECT_TRUE(showsProgress(true, nullptr));
    EXPECT_TRUE(showsProgress(true, ""));
    EXPECT_FALSE(showsProgress(true, "true"));
    EXPECT_FALSE(showsProgress(true, "1"));
    EXPECT_FALSE(showsProgress(false, nullptr));
}
