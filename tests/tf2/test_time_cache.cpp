#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/TimeCache.hpp"

#include <limits>
#include <vector>

using namespace tf2test;
using namespace ros2vtk::tf2;

namespace {

constexpr FrameId kParent = 1;
constexpr FrameId kOtherParent = 2;
constexpr FrameId kChild = 3;

TransformRecord record(TimePoint stamp, double x, FrameId parent = kParent,
  const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity())
{
  return TransformRecord{ stamp, make_transform({ x, 0, 0 }, q), parent, kChild };
}

std::vector<TimePoint> stamps(const TimeCache& cache)
{
  std::vector<TimePoint> out;
  for (const auto& r : cache.records())
  {
    out.push_back(r.stamp);
  }
  return out;
}

} // namespace

TEST(TimeCache, KeepsSamplesSortedWhateverTheArrivalOrder)
{
  TimeCache cache;
  EXPECT_TRUE(cache.insert(record(sec(3), 3)));
  EXPECT_TRUE(cache.insert(record(sec(1), 1)));
  EXPECT_TRUE(cache.insert(record(sec(2), 2)));
  EXPECT_EQ(stamps(cache), (std::vector<TimePoint>{ sec(1), sec(2), sec(3) }));
  EXPECT_EQ(cache.newest_stamp(), sec(3));
  EXPECT_EQ(cache.oldest_stamp(), sec(1));
  EXPECT_FALSE(cache.is_static());
}

TEST(TimeCache, StoresAnExactDuplicateOnce)
{
  TimeCache cache;
  EXPECT_TRUE(cache.insert(record(sec(1), 1)));
  EXPECT_TRUE(cache.insert(record(sec(1), 1)));
  EXPECT_EQ(cache.size(), 1u);
  // Same stamp, different value: both kept, the later arrival answers for the newest stamp.
  EXPECT_TRUE(cache.insert(record(sec(1), 7)));
  EXPECT_EQ(cache.size(), 2u);
  TransformRecord out;
  ASSERT_TRUE(cache.sample(sec(1), out));
  EXPECT_DOUBLE_EQ(out.transform.translation.x(), 7.0);
}

TEST(TimeCache, DropsSamplesOlderThanTheWindow)
{
  TimeCache cache; // 10 s
  cache.insert(record(sec(1), 1));
  cache.insert(record(sec(5), 5));
  cache.insert(record(sec(11), 11)); // 1 + 10 is not older than 11: kept
  EXPECT_EQ(stamps(cache), (std::vector<TimePoint>{ sec(1), sec(5), sec(11) }));
  cache.insert(record(sec(12), 12)); // 1 + 10 < 12: dropped
  EXPECT_EQ(stamps(cache), (std::vector<TimePoint>{ sec(5), sec(11), sec(12) }));
  cache.insert(record(sec(30), 30)); // everything else is older than 20 s
  EXPECT_EQ(stamps(cache), (std::vector<TimePoint>{ sec(30) }));
}

TEST(TimeCache, RejectsDataOlderThanTheWindowBehindTheNewest)
{
  TimeCache cache;
  cache.insert(record(sec(12), 12));
  EXPECT_FALSE(cache.insert(record(sec(1.5), 1.5))); // older than 12 - 10
  EXPECT_TRUE(cache.insert(record(sec(2), 2)));      // exactly 12 - 10: still accepted
  EXPECT_TRUE(cache.insert(record(sec(7), 7)));      // late but inside the window
  EXPECT_EQ(stamps(cache), (std::vector<TimePoint>{ sec(2), sec(7), sec(12) }));
}

TEST(TimeCache, CustomWindow)
{
  TimeCache cache(sec(1));
  EXPECT_EQ(cache.cache_time(), sec(1));
  cache.insert(record(sec(1), 1));
  cache.insert(record(sec(2.5), 2.5));
  EXPECT_EQ(stamps(cache), (std::vector<TimePoint>{ sec(2.5) }));
  EXPECT_FALSE(cache.insert(record(sec(1.4), 1.4)));
}

TEST(TimeCache, EmptyCacheHasNoData)
{
  TimeCache cache;
  TransformRecord out;
  SampleError error;
  EXPECT_FALSE(cache.sample(sec(1), out, &error));
  EXPECT_EQ(error.code, Tf2Error::NoDataForExtrapolation);
  EXPECT_FALSE(cache.sample(kLatestTime, out, &error));
  EXPECT_EQ(cache.parent_at(kLatestTime), kNoFrame);
  EXPECT_EQ(cache.latest_time_and_parent(), (std::pair<TimePoint, FrameId>{ 0, kNoFrame }));
}

TEST(TimeCache, SingleSampleAnswersOnlyItsOwnStampOrLatest)
{
  TimeCache cache;
  cache.insert(record(sec(5), 5));
  TransformRecord out;
  ASSERT_TRUE(cache.sample(sec(5), out));
  EXPECT_DOUBLE_EQ(out.transform.translation.x(), 5.0);
  ASSERT_TRUE(cache.sample(kLatestTime, out));
  EXPECT_EQ(out.stamp, sec(5));

  SampleError error;
  EXPECT_FALSE(cache.sample(sec(6), out, &error));
  EXPECT_EQ(error.code, Tf2Error::NoDataForExtrapolation);
  EXPECT_EQ(error.message,
    "Lookup would require extrapolation at time 6.000000, but only time 5.000000 is in the buffer");
}

TEST(TimeCache, ForwardAndBackwardExtrapolationAreRefused)
{
  TimeCache cache;
  cache.insert(record(sec(2), 2));
  cache.insert(record(sec(4), 4));
  TransformRecord out;
  SampleError error;
  EXPECT_FALSE(cache.sample(sec(4.5), out, &error));
  EXPECT_EQ(error.code, Tf2Error::ForwardExtrapolation);
  EXPECT_EQ(error.message,
    "Lookup would require extrapolation into the future.  Requested time "
    "4.500000 but the latest data is at time 4.000000");
  EXPECT_FALSE(cache.sample(sec(1), out, &error));
  EXPECT_EQ(error.code, Tf2Error::BackwardExtrapolation);
  EXPECT_EQ(error.message,
    "Lookup would require extrapolation into the past.  Requested time "
    "1.000000 but the earliest data is at time 2.000000");
}

TEST(TimeCache, InterpolatesAtTheMidpoint)
{
  TimeCache cache;
  cache.insert(record(sec(1), 0, kParent));
  cache.insert(
    TransformRecord{ sec(3), make_transform({ 2, 4, -6 }, about(0, 0, 1, 90)), kParent, kChild });
  TransformRecord out;
  ASSERT_TRUE(cache.sample(sec(2), out));
  EXPECT_TRUE(same_vector(out.transform.translation, { 1, 2, -3 }));
  EXPECT_TRUE(same_rotation(out.transform.rotation, about(0, 0, 1, 45)));
  EXPECT_EQ(out.stamp, sec(2));
  EXPECT_EQ(out.parent, kParent);

  ASSERT_TRUE(cache.sample(sec(1.5), out)); // a quarter of the way
  EXPECT_TRUE(same_vector(out.transform.translation, { 0.5, 1, -1.5 }));
  EXPECT_TRUE(same_rotation(out.transform.rotation, about(0, 0, 1, 22.5)));
}

TEST(TimeCache, ExactStampsReturnTheStoredSample)
{
  TimeCache cache;
  cache.insert(record(sec(1), 10));
  cache.insert(record(sec(2), 20));
  cache.insert(record(sec(3), 30));
  TransformRecord out;
  for (double s : { 1.0, 2.0, 3.0 })
  {
    ASSERT_TRUE(cache.sample(sec(s), out));
    EXPECT_DOUBLE_EQ(out.transform.translation.x(), 10 * s);
  }
  ASSERT_TRUE(cache.sample(kLatestTime, out));
  EXPECT_DOUBLE_EQ(out.transform.translation.x(), 30.0);
  EXPECT_EQ(out.stamp, sec(3));
}

TEST(TimeCache, NoInterpolationAcrossAParentChange)
{
  TimeCache cache;
  cache.insert(record(sec(1), 1, kParent));
  cache.insert(record(sec(2), 2, kParent));
  cache.insert(record(sec(3), 50, kOtherParent));
  TransformRecord out;
  ASSERT_TRUE(cache.sample(sec(2.5), out));
  EXPECT_EQ(out.parent, kParent);                       // the older sample's parent...
  EXPECT_DOUBLE_EQ(out.transform.translation.x(), 2.0); // ...and its value, not a blend
  EXPECT_EQ(cache.parent_at(sec(2.5)), kParent);
  EXPECT_EQ(cache.parent_at(sec(3)), kOtherParent);
  EXPECT_EQ(cache.parent_at(sec(1.5)), kParent);
  EXPECT_EQ(
    cache.latest_time_and_parent(), (std::pair<TimePoint, FrameId>{ sec(3), kOtherParent }));
  EXPECT_EQ(cache.parent_at(sec(4)), kNoFrame); // forward extrapolation
}

TEST(TimeCache, ClearForgetsEverything)
{
  TimeCache cache;
  cache.insert(record(sec(1), 1));
  cache.clear();
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(cache.newest_stamp(), 0);
  // After a clear, old stamps are welcome again (e.g. a replayed bag).
  EXPECT_TRUE(cache.insert(record(sec(0.5), 0.5)));
}

TEST(TimeCache, ExtremeStampsDoNotOverflowTheWindowArithmetic)
{
  // Stamps come from the network: any int64 is possible. newest - cache_time must not wrap.
  constexpr TimePoint kMin = std::numeric_limits<TimePoint>::min();
  constexpr TimePoint kMax = std::numeric_limits<TimePoint>::max();
  TimeCache cache;
  EXPECT_TRUE(cache.insert(record(kMin + 1, 1)));
  EXPECT_TRUE(cache.insert(record(kMin + 2, 2)));
  EXPECT_EQ(stamps(cache), (std::vector<TimePoint>{ kMin + 1, kMin + 2 }));
  EXPECT_TRUE(cache.insert(record(kMax, 3))); // the others are far more than 10 s older
  EXPECT_EQ(stamps(cache), (std::vector<TimePoint>{ kMax }));
  EXPECT_FALSE(cache.insert(record(kMin + 3, 4)));
  TransformRecord out;
  EXPECT_TRUE(cache.sample(kLatestTime, out));
}
