#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/TimePoint.hpp"

using namespace ros2vtk::tf2;

TEST(TimePoint, FromSecNanosec)
{
  EXPECT_EQ(time_from_sec_nanosec(12, 500'000'000), 12'500'000'000);
  EXPECT_EQ(time_from_sec_nanosec(0, 1), 1);
  EXPECT_EQ(time_from_sec_nanosec(-1, 0), -1'000'000'000);
}

TEST(TimePoint, SecondsConversions)
{
  EXPECT_EQ(time_from_seconds(1.25), 1'250'000'000);
  EXPECT_DOUBLE_EQ(time_to_seconds(2'500'000'000), 2.5);
}

TEST(TimePoint, DisplaysLikeTf2WithSixDecimals)
{
  EXPECT_EQ(display_time(12'500'000'000), "12.500000");
  EXPECT_EQ(display_time(0), "0.000000");
  EXPECT_EQ(display_time(1'000'001'000), "1.000001");
}

TEST(TimePoint, DefaultCacheIsTenSeconds)
{
  EXPECT_EQ(kDefaultCacheTime, 10 * 1'000'000'000LL);
  EXPECT_EQ(kLatestTime, 0);
}
