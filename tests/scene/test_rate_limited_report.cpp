#include "Internal/RateLimitedReport.hpp"

#include <gtest/gtest.h>

using ros2vtk::scene::RateLimitedReport;
using namespace std::chrono_literals;

TEST(RateLimitedReport, ReportsTheFirstAtOnceThenSumsUntilTheIntervalHasPassed)
{
  RateLimitedReport report(5s);
  const auto t0 = RateLimitedReport::Clock::time_point{} + 100s;
  EXPECT_EQ(report.record(0, t0), 0u);      // nothing happened
  EXPECT_EQ(report.record(3, t0), 3u);      // first: at once
  EXPECT_EQ(report.record(2, t0 + 1s), 0u); // within the interval: held
  EXPECT_EQ(report.record(4, t0 + 4s), 0u);
  EXPECT_EQ(report.record(0, t0 + 5s), 6u);  // interval over: the sum, even with no new ones
  EXPECT_EQ(report.record(0, t0 + 20s), 0u); // nothing pending
  EXPECT_EQ(report.record(1, t0 + 20s), 1u); // quiet long enough: at once again
}
