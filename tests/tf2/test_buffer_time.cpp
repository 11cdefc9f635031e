// Time in lookups: interpolation, latest common time, static frames, expiry, extrapolation.
#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/BufferCore.hpp"

using namespace tf2test;
using namespace ros2vtk::tf2;

TEST(BufferTime, InterpolatesBetweenTwoStamps)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(10), { 0, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(
    make_stamped("world", "base", sec(12), { 4, -2, 8 }, about(0, 1, 0, 90)), "x"));
  const LookupResult r = buffer.lookup_transform("world", "base", sec(11));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, sec(11));
  EXPECT_TRUE(same_vector(r.transform.translation, { 2, -1, 4 }));
  EXPECT_TRUE(same_rotation(r.transform.rotation, about(0, 1, 0, 45)));
  // The inverse direction interpolates the same sample, then inverts it.
  const LookupResult back = buffer.lookup_transform("base", "world", sec(11));
  ASSERT_TRUE(back.ok) << back.message;
  EXPECT_TRUE(same_rotation(back.transform.rotation, about(0, 1, 0, -45)));
  EXPECT_TRUE(same_vector(back.transform.apply(r.transform.apply({ 1, 2, 3 })), { 1, 2, 3 }));
}

TEST(BufferTime, LatestCommonTimeIsTheOldestNewestStampOnThePath)
{
  BufferCore buffer;
  // world -> base: newest 10 s. base -> arm: newest 7 s. arm -> hand: static.
  ASSERT_TRUE(buffer.set_transform(
    make_stamped("world", "base", sec(6), { 1, 0, 0 }, about(0, 0, 1, 90)), "x"));
  ASSERT_TRUE(buffer.set_transform(
    make_stamped("world", "base", sec(10), { 3, 0, 0 }, about(0, 0, 1, 90)), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "arm", sec(6), { 0, 2, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "arm", sec(7), { 0, 4, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("arm", "hand", sec(0), { 0, 0, 1 }), "x", true));

  LookupResult r = buffer.lookup_transform("world", "arm", kLatestTime);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, sec(7));
  // At 7 s: base at (1 + 2 * 1/4, 0, 0) = (1.5, 0, 0); arm (0,4,0) rotated by Rz90 = (-4,0,0).
  EXPECT_TRUE(same_vector(r.transform.translation, { -2.5, 0, 0 }));

  // The static link adds no constraint.
  r = buffer.lookup_transform("world", "hand", kLatestTime);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, sec(7));
  EXPECT_TRUE(same_vector(r.transform.translation, { -2.5, 0, 1 }));

  // Inside the subtree under base only arm's stamps count, world -> base does not.
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "sensor", sec(5), { 0, 0, 3 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "sensor", sec(9), { 0, 0, 3 }), "x"));
  r = buffer.lookup_transform("sensor", "hand", kLatestTime);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, sec(7));
  r = buffer.lookup_transform("sensor", "base", kLatestTime);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, sec(9));
  r = buffer.lookup_transform("base", "sensor", kLatestTime);
  EXPECT_EQ(r.stamp, sec(9));
}

TEST(BufferTime, StaticFramesHoldAtAnyTime)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "map", sec(0), { 0, 5, 0 }), "s", true));
  for (TimePoint t : { sec(0.001), sec(123), sec(1e6) })
  {
    const LookupResult r = buffer.lookup_transform("world", "map", t);
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_EQ(r.stamp, t);
    EXPECT_TRUE(same_vector(r.transform.translation, { 0, 5, 0 }));
  }
  // All-static path at time 0: the stamp stays 0.
  LookupResult r = buffer.lookup_transform("map", "world", kLatestTime);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, 0);
  EXPECT_TRUE(same_vector(r.transform.translation, { 0, -5, 0 }));

  // A dynamic frame below the static one: its stamps alone decide.
  ASSERT_TRUE(buffer.set_transform(make_stamped("map", "robot", sec(2), { 1, 0, 0 }), "d"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("map", "robot", sec(4), { 3, 0, 0 }), "d"));
  r = buffer.lookup_transform("world", "robot", sec(3));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(same_vector(r.transform.translation, { 2, 5, 0 }));
  r = buffer.lookup_transform("world", "robot", kLatestTime);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, sec(4));
  EXPECT_TRUE(same_vector(r.transform.translation, { 3, 5, 0 }));
}

TEST(BufferTime, SamplesExpireTenSecondsBehindTheNewest)
{
  BufferCore buffer;
  for (double s : { 1.0, 5.0, 11.0 })
  {
    ASSERT_TRUE(buffer.set_transform(make_stamped("a", "b", sec(s), { s, 0, 0 }), "x"));
  }
  ASSERT_TRUE(buffer.lookup_transform("a", "b", sec(3)).ok); // 1 s still there
  ASSERT_TRUE(buffer.set_transform(make_stamped("a", "b", sec(12), { 12, 0, 0 }), "x"));
  const LookupResult r = buffer.lookup_transform("a", "b", sec(3));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error, Tf2Error::BackwardExtrapolation);
  EXPECT_EQ(r.message,
    "Lookup would require extrapolation into the past.  Requested time "
    "3.000000 but the earliest data is at time 5.000000, when looking up "
    "transform from frame [b] to frame [a]");
  const LookupResult kept = buffer.lookup_transform("a", "b", sec(8));
  ASSERT_TRUE(kept.ok) << kept.message;
  EXPECT_TRUE(same_vector(kept.transform.translation, { 8, 0, 0 }));
}

TEST(BufferTime, ForwardExtrapolationMessage)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("a", "b", sec(1), { 0, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("a", "b", sec(2.5), { 0, 0, 0 }), "x"));
  const LookupResult r = buffer.lookup_transform("b", "a", sec(3));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error, Tf2Error::ForwardExtrapolation);
  EXPECT_TRUE(is_extrapolation(r.error));
  EXPECT_EQ(r.message,
    "Lookup would require extrapolation into the future.  Requested time "
    "3.000000 but the latest data is at time 2.500000, when looking up "
    "transform from frame [a] to frame [b]");
}

TEST(BufferTime, SingleSampleNeedsAnExactStamp)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("a", "b", sec(5), { 1, 0, 0 }), "x"));
  EXPECT_TRUE(buffer.lookup_transform("a", "b", sec(5)).ok);
  const LookupResult r = buffer.lookup_transform("a", "b", sec(5.25));
  EXPECT_EQ(r.error, Tf2Error::NoDataForExtrapolation);
  EXPECT_EQ(r.message,
    "Lookup would require extrapolation at time 5.250000, but only time "
    "5.000000 is in the buffer, when looking up transform from frame [b] to "
    "frame [a]");
}

TEST(BufferTime, ClearForgetsDynamicHistoryButNotStaticFrames)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "map", sec(0), { 0, 5, 0 }), "s", true));
  ASSERT_TRUE(buffer.set_transform(make_stamped("map", "robot", sec(20), { 1, 0, 0 }), "d"));
  buffer.clear();
  EXPECT_TRUE(buffer.lookup_transform("world", "map", sec(1)).ok);
  LookupResult r = buffer.lookup_transform("world", "robot", sec(20));
  EXPECT_EQ(r.error, Tf2Error::NoDataForExtrapolation) << r.message;
  r = buffer.lookup_transform("world", "robot", kLatestTime);
  EXPECT_FALSE(r.ok);
  // Time went backwards (e.g. a restarted simulation): older stamps are accepted again.
  ASSERT_TRUE(buffer.set_transform(make_stamped("map", "robot", sec(1), { 2, 0, 0 }), "d"));
  r = buffer.lookup_transform("world", "robot", kLatestTime);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, sec(1));
  EXPECT_TRUE(same_vector(r.transform.translation, { 2, 5, 0 }));
}
