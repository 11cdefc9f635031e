// ros2vtk — unit tests of ROSClock: rcl's ROS clock with a time override (rcl/src/rcl/time.c:
// the override is 0 until set, keeps its value across disable/enable) and the jump count a tf
// buffer clears itself on (tf2_ros::Buffer::onTimeJump: a change of source or a jump back).
// The system time is injected, so no expectation depends on the real clock.
#include "ros2vtk/wire/ROSClock.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace {

using ros2vtk::wire::ROSClock;

constexpr int64_t kWall = 1'764'000'000'123'456'789; // a 2025 wall-clock time, in ns
constexpr int64_t kSim = 1'000'000'000'000;          // 1000 s: a simulator's epoch

ROSClock fixed_wall_clock()
{
  return ROSClock([] { return kWall; });
}

TEST(ROSClock, FollowsTheSystemClockUntilSimulatedTimeIsOn)
{
  ROSClock clock = fixed_wall_clock();
  EXPECT_FALSE(clock.is_sim_time_active());
  EXPECT_EQ(clock.now(), kWall);
  clock.set_sim_time(kSim); // /clock heard while off: remembered, not used
  EXPECT_EQ(clock.now(), kWall);
  EXPECT_TRUE(clock.has_sim_time());
}

TEST(ROSClock, IsZeroBeforeTheFirstSimulatedTimeNeverTheWallClock)
{
  ROSClock clock = fixed_wall_clock();
  clock.set_sim_time_active(true);
  EXPECT_EQ(clock.now(), 0);
  EXPECT_FALSE(clock.has_sim_time());
  clock.set_sim_time(kSim + 5);
  EXPECT_EQ(clock.now(), kSim + 5);
  clock.set_sim_time(kSim + 7);
  EXPECT_EQ(clock.now(), kSim + 7);
}

TEST(ROSClock, KeepsTheSimulatedTimeAcrossOffAndOn)
{
  ROSClock clock = fixed_wall_clock();
  clock.set_sim_time_active(true);
  clock.set_sim_time(kSim);
  clock.set_sim_time_active(false);
  EXPECT_EQ(clock.now(), kWall);
  clock.set_sim_time_active(true);
  EXPECT_EQ(clock.now(), kSim);
}

TEST(ROSClock, CountsSourceChangesAndJumpsBackOnly)
{
  ROSClock clock = fixed_wall_clock();
  EXPECT_EQ(clock.jump_count(), 0u);
  clock.set_sim_time_active(false); // no change
  EXPECT_EQ(clock.jump_count(), 0u);
  clock.set_sim_time_active(true);
  EXPECT_EQ(clock.jump_count(), 1u);
  clock.set_sim_time(kSim);
  clock.set_sim_time(kSim + 1);
  clock.set_sim_time(kSim + 1); // standing still is no jump
  EXPECT_EQ(clock.jump_count(), 1u);
  clock.set_sim_time(kSim - 10); // a replay restarting
  EXPECT_EQ(clock.jump_count(), 2u);
  clock.set_sim_time_active(false);
  EXPECT_EQ(clock.jump_count(), 3u);
  clock.set_sim_time(0); // going back while off moves nothing a node stamps with
  EXPECT_EQ(clock.jump_count(), 3u);
}

TEST(ROSClock, DefaultsToTheRealSystemClock)
{
  ROSClock clock;
  const int64_t before = std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::system_clock::now().time_since_epoch())
                           .count();
  const int64_t now = clock.now();
  const int64_t after = std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::system_clock::now().time_since_epoch())
                          .count();
  EXPECT_LE(before, now);
  EXPECT_LE(now, after);
}

} // namespace
