#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/StaticCache.hpp"

using namespace tf2test;
using namespace ros2vtk::tf2;

TEST(StaticCache, LastValueHoldsAtEveryTime)
{
  StaticCache cache;
  TransformRecord out;
  SampleError error;
  EXPECT_FALSE(cache.sample(sec(1), out, &error));
  EXPECT_EQ(error.code, Tf2Error::NoDataForExtrapolation);

  cache.insert(TransformRecord{ sec(5), make_transform({ 1, 0, 0 }), 1, 2 });
  cache.insert(TransformRecord{ sec(6), make_transform({ 2, 0, 0 }), 1, 2 });
  for (TimePoint t : { TimePoint(0), sec(1), sec(6), sec(1e6) })
  {
    ASSERT_TRUE(cache.sample(t, out));
    EXPECT_DOUBLE_EQ(out.transform.translation.x(), 2.0);
    EXPECT_EQ(out.stamp, t); // stamped with the requested time, as tf2 does
  }
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.parent_at(sec(123)), 1u);
}

TEST(StaticCache, NeverConstrainsTheLatestCommonTime)
{
  StaticCache cache;
  cache.insert(TransformRecord{ sec(5), make_transform({ 1, 0, 0 }), 7, 2 });
  EXPECT_EQ(cache.latest_time_and_parent(), (std::pair<TimePoint, FrameId>{ 0, 7 }));
  EXPECT_EQ(cache.newest_stamp(), 0);
  EXPECT_EQ(cache.oldest_stamp(), 0);
  EXPECT_TRUE(cache.is_static());
}

TEST(StaticCache, SurvivesClear)
{
  StaticCache cache;
  cache.insert(TransformRecord{ sec(5), make_transform({ 1, 0, 0 }), 7, 2 });
  cache.clear();
  TransformRecord out;
  EXPECT_TRUE(cache.sample(sec(1), out));
}
