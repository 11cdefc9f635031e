#include "Internal/LinkStateMonitor.hpp"

#include <gtest/gtest.h>

using ros2vtk::scene::LinkStateMonitor;
using namespace std::chrono_literals;

TEST(LinkStateMonitor, ReportsEachChangeOfThePeerCountOnce)
{
  LinkStateMonitor monitor(5s, 60s);
  const auto t0 = LinkStateMonitor::Clock::time_point{} + 100s;
  monitor.start(t0);
  EXPECT_FALSE(monitor.update(0, t0 + 1s)); // nobody yet, as at the start
  EXPECT_TRUE(monitor.update(1, t0 + 2s));  // a peer found
  EXPECT_FALSE(monitor.update(1, t0 + 3s));
  EXPECT_TRUE(monitor.update(2, t0 + 4s));  // another one
  EXPECT_TRUE(monitor.update(0, t0 + 30s)); // both dropped (a cut link)
  EXPECT_FALSE(monitor.update(0, t0 + 31s));
  EXPECT_TRUE(monitor.update(1, t0 + 40s)); // healed
}

TEST(LinkStateMonitor, SaysItFoundNobodyAfterTheQuietTimeThenAtMostOncePerInterval)
{
  LinkStateMonitor monitor(5s, 60s);
  const auto t0 = LinkStateMonitor::Clock::time_point{} + 100s;
  monitor.start(t0);
  EXPECT_LT(monitor.alone_report_due(t0 + 4s), 0.0); // too early
  EXPECT_DOUBLE_EQ(monitor.alone_report_due(t0 + 5s), 5.0);
  EXPECT_DOUBLE_EQ(monitor.alone_report_due(t0 + 5s), 5.0); // due until reported
  monitor.alone_reported(t0 + 5s);
  EXPECT_LT(monitor.alone_report_due(t0 + 64s), 0.0); // within the minute: quiet
  EXPECT_DOUBLE_EQ(monitor.alone_report_due(t0 + 65s), 65.0);
  monitor.alone_reported(t0 + 65s);
  monitor.update(1, t0 + 70s); // a peer: nothing to say
  EXPECT_LT(monitor.alone_report_due(t0 + 200s), 0.0);
  monitor.update(0, t0 + 200s); // lost again: the quiet time starts over
  EXPECT_LT(monitor.alone_report_due(t0 + 204s), 0.0);
  EXPECT_DOUBLE_EQ(monitor.alone_report_due(t0 + 205s), 5.0);
}
