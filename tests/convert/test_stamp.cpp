// Header stamps from the system clock.
#include "ros2vtk/convert/Stamp.hpp"

#include <gtest/gtest.h>

#include <chrono>

using namespace ros2vtk::convert;

TEST(Stamp, SplitsATimePointIntoSecondsAndNanoseconds)
{
  const auto time = std::chrono::system_clock::time_point(
    std::chrono::duration_cast<std::chrono::system_clock::duration>(
      std::chrono::seconds(1700000000) + std::chrono::nanoseconds(123456789)));
  const Stamp stamp = to_stamp(time);
  EXPECT_EQ(stamp.sec, 1700000000);
  EXPECT_EQ(stamp.nanosec, 123456789u);
}

TEST(Stamp, ClampsWhatInt32SecondsCannotHold)
{
  const Stamp before_epoch = to_stamp(std::chrono::system_clock::time_point(
    std::chrono::duration_cast<std::chrono::system_clock::duration>(std::chrono::seconds(-5))));
  EXPECT_EQ(before_epoch.sec, 0);
  EXPECT_EQ(before_epoch.nanosec, 0u);
  const Stamp after_2038 = to_stamp(std::chrono::system_clock::time_point(
    std::chrono::duration_cast<std::chrono::system_clock::duration>(
      std::chrono::seconds(3000000000LL))));
  EXPECT_EQ(after_2038.sec, 2147483647);
  EXPECT_EQ(after_2038.nanosec, 999999999u);
}

TEST(Stamp, NowIsTheSystemClock)
{
  const auto before = std::chrono::system_clock::now();
  const Stamp stamp = now_stamp();
  const auto after = std::chrono::system_clock::now();
  const auto seconds = [](std::chrono::system_clock::time_point t) {
    return std::chrono::duration_cast<std::chrono::seconds>(t.time_since_epoch()).count();
  };
  EXPECT_GE(stamp.sec, seconds(before));
  EXPECT_LE(stamp.sec, seconds(after));
  EXPECT_LT(stamp.nanosec, 1000000000u);
  EXPECT_GT(stamp.sec, 1600000000); // not zero: broadcasts carry the real time
}
