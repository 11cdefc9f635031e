// lookupTransform / canTransform through the tree: chains, errors, loops, parent changes.
#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/BufferCore.hpp"

using namespace tf2test;
using namespace ros2vtk::tf2;

namespace {

/// world
///  └ base     (1,0,0), 90 deg about z
///     ├ arm   (0,2,0)
///     │  └ hand (0,0,1)
///     └ sensor (0,0,3), 180 deg about x
/// every frame with one sample at t = 5 s.
void add_robot(BufferCore& buffer, TimePoint t = sec(5))
{
  ASSERT_TRUE(buffer.set_transform(
    make_stamped("world", "base", t, { 1, 0, 0 }, about(0, 0, 1, 90)), "robot"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "arm", t, { 0, 2, 0 }), "robot"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("arm", "hand", t, { 0, 0, 1 }), "robot"));
  ASSERT_TRUE(buffer.set_transform(
    make_stamped("base", "sensor", t, { 0, 0, 3 }, about(1, 0, 0, 180)), "robot"));
}

} // namespace

TEST(BufferLookup, DirectParent)
{
  BufferCore buffer;
  add_robot(buffer);
  const LookupResult r = buffer.lookup_transform("base", "arm", sec(5));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.error, Tf2Error::NoError);
  EXPECT_TRUE(r.message.empty());
  EXPECT_EQ(r.target_frame, "base");
  EXPECT_EQ(r.source_frame, "arm");
  EXPECT_EQ(r.stamp, sec(5));
  EXPECT_TRUE(same_vector(r.transform.translation, { 0, 2, 0 }));
  EXPECT_TRUE(same_rotation(r.transform.rotation, Eigen::Quaterniond::Identity()));
}

TEST(BufferLookup, GrandchildToRoot)
{
  BufferCore buffer;
  add_robot(buffer);
  const LookupResult r = buffer.lookup_transform("world", "hand", sec(5));
  ASSERT_TRUE(r.ok) << r.message;
  // hand origin is (0,2,1) in base; Rz90 maps it to (-2,0,1); plus (1,0,0).
  EXPECT_TRUE(same_vector(r.transform.translation, { -1, 0, 1 }));
  EXPECT_TRUE(same_rotation(r.transform.rotation, about(0, 0, 1, 90)));
  EXPECT_TRUE(same_vector(r.isometry() * Eigen::Vector3d(1, 0, 0), { -1, 1, 1 }));
}

TEST(BufferLookup, RootToGrandchildIsTheInverse)
{
  BufferCore buffer;
  add_robot(buffer);
  const LookupResult r = buffer.lookup_transform("hand", "world", sec(5));
  ASSERT_TRUE(r.ok) << r.message;
  // world origin in base: Rz(-90) * (-1,0,0) = (0,1,0); in hand: minus (0,2,1).
  EXPECT_TRUE(same_vector(r.transform.translation, { 0, -1, -1 }));
  EXPECT_TRUE(same_rotation(r.transform.rotation, about(0, 0, 1, -90)));
}

TEST(BufferLookup, GrandchildToSiblingSubtree)
{
  BufferCore buffer;
  add_robot(buffer);
  const LookupResult r = buffer.lookup_transform("sensor", "hand", sec(5));
  ASSERT_TRUE(r.ok) << r.message;
  // hand origin in base (0,2,1); minus sensor offset (0,0,3) = (0,2,-2); Rx180 -> (0,-2,2).
  EXPECT_TRUE(same_vector(r.transform.translation, { 0, -2, 2 }));
  EXPECT_TRUE(same_rotation(r.transform.rotation, about(1, 0, 0, 180)));
  // Point (1,0,0) of hand: (1,2,1) in base -> (1,2,-2) -> (1,-2,2).
  EXPECT_TRUE(same_vector(r.transform.apply({ 1, 0, 0 }), { 1, -2, 2 }));
}

TEST(BufferLookup, SubtreeLookupIgnoresStaleFramesAboveTheCommonParent)
{
  BufferCore buffer;
  add_robot(buffer, sec(5));
  // arm/hand/sensor move on to t = 6 s; world -> base stays at 5 s.
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "arm", sec(6), { 0, 2, 0 }), "robot"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("arm", "hand", sec(6), { 0, 0, 1 }), "robot"));
  ASSERT_TRUE(buffer.set_transform(
    make_stamped("base", "sensor", sec(6), { 0, 0, 3 }, about(1, 0, 0, 180)), "robot"));
  const LookupResult r = buffer.lookup_transform("sensor", "hand", sec(5.5));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(same_vector(r.transform.translation, { 0, -2, 2 }));
  // To world, the same time needs base at 5.5 s, which is beyond its data.
  const LookupResult up = buffer.lookup_transform("world", "hand", sec(5.5));
  EXPECT_FALSE(up.ok);
  EXPECT_EQ(up.error, Tf2Error::NoDataForExtrapolation);
}

TEST(BufferLookup, SameFrameIsIdentityEvenWhenUnknown)
{
  BufferCore buffer;
  LookupResult r = buffer.lookup_transform("nowhere", "nowhere", sec(3));
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.stamp, sec(3));
  EXPECT_TRUE(same_vector(r.transform.translation, { 0, 0, 0 }));
  r = buffer.lookup_transform("nowhere", "nowhere", kLatestTime);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.stamp, 0);

  add_robot(buffer, sec(7));
  r = buffer.lookup_transform("arm", "arm", kLatestTime);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.stamp, sec(7)); // newest stamp of that frame
}

TEST(BufferLookup, UnknownFramesAreLookupErrors)
{
  BufferCore buffer;
  add_robot(buffer);
  LookupResult r = buffer.lookup_transform("map", "base", sec(5));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error, Tf2Error::Lookup);
  EXPECT_EQ(r.message, "\"map\" passed to lookupTransform argument target_frame does not exist.");
  r = buffer.lookup_transform("base", "laser", sec(5));
  EXPECT_EQ(r.error, Tf2Error::Lookup);
  EXPECT_EQ(r.message, "\"laser\" passed to lookupTransform argument source_frame does not exist.");

  std::string error;
  EXPECT_FALSE(buffer.can_transform("map", "base", sec(5), &error));
  EXPECT_EQ(error, "\"map\" passed to canTransform argument target_frame does not exist.");
}

TEST(BufferLookup, EmptyOrSlashedNamesAreInvalidArguments)
{
  BufferCore buffer;
  add_robot(buffer);
  LookupResult r = buffer.lookup_transform("", "base", sec(5));
  EXPECT_EQ(r.error, Tf2Error::InvalidArgument);
  EXPECT_EQ(r.message,
    "Invalid argument \"\" passed to lookupTransform argument target_frame - "
    "in tf2 frame_ids cannot be empty");
  r = buffer.lookup_transform("world", "/base", sec(5));
  EXPECT_EQ(r.error, Tf2Error::InvalidArgument);
  EXPECT_EQ(r.message,
    "Invalid argument \"/base\" passed to lookupTransform argument "
    "source_frame - in tf2 frame_ids cannot start with a '/'");
}

TEST(BufferLookup, DisconnectedTrees)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "a", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("map", "b", sec(1), { 1, 0, 0 }), "x"));
  const std::string expected = "Could not find a connection between 'a' and 'b' because they "
                               "are not part of the same tree.Tf has two or more unconnected "
                               "trees.";
  for (TimePoint t : { kLatestTime, sec(1) })
  {
    const LookupResult r = buffer.lookup_transform("a", "b", t);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.error, Tf2Error::Connectivity);
    EXPECT_EQ(r.message, expected);
  }
  // Two roots known only as parents are disconnected too.
  const LookupResult roots = buffer.lookup_transform("world", "map", sec(1));
  EXPECT_EQ(roots.error, Tf2Error::Connectivity);
  std::string error;
  EXPECT_FALSE(buffer.can_transform("a", "b", sec(1), &error));
  EXPECT_EQ(error, expected);
}

TEST(BufferLookup, TwoFrameLoopIsDetected)
{
  BufferCore buffer;
  // a is b's parent and b is a's parent: each insert is valid on its own.
  ASSERT_TRUE(buffer.set_transform(make_stamped("a", "b", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("b", "a", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("other", "c", sec(1), { 1, 0, 0 }), "x"));
  for (TimePoint t : { kLatestTime, sec(1) })
  {
    const LookupResult r = buffer.lookup_transform("c", "a", t);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.error, Tf2Error::Lookup);
    EXPECT_EQ(r.message.rfind("The tf tree is invalid because it contains a loop.\n", 0), 0u)
      << r.message;
    EXPECT_NE(r.message.find("Frame a exists with parent b."), std::string::npos) << r.message;
    const LookupResult reverse = buffer.lookup_transform("a", "c", t);
    EXPECT_EQ(reverse.error, Tf2Error::Lookup) << reverse.message;
  }
  // Between the two frames of the loop the direct link still answers, as in tf2.
  const LookupResult direct = buffer.lookup_transform("b", "a", sec(1));
  ASSERT_TRUE(direct.ok) << direct.message;
  EXPECT_TRUE(same_vector(direct.transform.translation, { 1, 0, 0 }));
}

TEST(BufferLookup, LongerLoopBelowALeafIsDetected)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("p", "q", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("q", "r", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("r", "p", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("q", "leaf", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("elsewhere", "z", sec(1), { 1, 0, 0 }), "x"));
  const LookupResult r = buffer.lookup_transform("z", "leaf", sec(1));
  EXPECT_EQ(r.error, Tf2Error::Lookup);
  EXPECT_NE(r.message.find("contains a loop"), std::string::npos) << r.message;
}

TEST(BufferLookup, ParentSwitchingOverTime)
{
  BufferCore buffer;
  // tool hangs from "left" until 2 s, from "right" from 3 s on.
  ASSERT_TRUE(buffer.set_transform(make_stamped("left", "tool", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("left", "tool", sec(2), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("right", "tool", sec(3), { 5, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("right", "tool", sec(4), { 7, 0, 0 }), "x"));

  std::string parent;
  ASSERT_TRUE(buffer.get_frame_parent("tool", sec(1.5), parent));
  EXPECT_EQ(parent, "left");
  ASSERT_TRUE(buffer.get_frame_parent("tool", sec(2.5), parent));
  EXPECT_EQ(parent, "left");
  ASSERT_TRUE(buffer.get_frame_parent("tool", sec(3.5), parent));
  EXPECT_EQ(parent, "right");
  ASSERT_TRUE(buffer.get_frame_parent("tool", kLatestTime, parent));
  EXPECT_EQ(parent, "right");
  EXPECT_FALSE(buffer.get_frame_parent("tool", sec(9), parent));
  EXPECT_FALSE(buffer.get_frame_parent("left", sec(1), parent)); // a root
  EXPECT_FALSE(buffer.get_frame_parent("unknown", sec(1), parent));

  // Between 2 s and 3 s the older sample holds, unblended.
  LookupResult r = buffer.lookup_transform("left", "tool", sec(2.5));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(same_vector(r.transform.translation, { 1, 0, 0 }));
  r = buffer.lookup_transform("right", "tool", sec(2.5));
  EXPECT_EQ(r.error, Tf2Error::Connectivity) << r.message;
  // Within the "right" period interpolation works again: midway between 5 and 7.
  r = buffer.lookup_transform("right", "tool", sec(3.5));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(same_vector(r.transform.translation, { 6, 0, 0 }));
  // Latest: the newest sample, under its parent.
  r = buffer.lookup_transform("right", "tool", kLatestTime);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.stamp, sec(4));
  EXPECT_TRUE(same_vector(r.transform.translation, { 7, 0, 0 }));
}

TEST(BufferLookup, TimeTravelThroughAFixedFrame)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(2), { 3, 0, 0 }), "x"));
  // Where the base was at 1 s, seen from the base at 2 s: (1,0,0) - (3,0,0).
  const LookupResult r = buffer.lookup_transform("base", sec(2), "base", sec(1), "world");
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_TRUE(same_vector(r.transform.translation, { -2, 0, 0 }));
  EXPECT_EQ(r.stamp, sec(2));
  EXPECT_EQ(r.target_frame, "base");
  EXPECT_EQ(r.source_frame, "base");
  EXPECT_TRUE(buffer.can_transform("base", sec(2), "base", sec(1), "world"));

  std::string error;
  EXPECT_FALSE(buffer.can_transform("base", sec(2), "base", sec(1), "odom", &error));
  EXPECT_EQ(error, "\"odom\" passed to lookupTransform argument fixed_frame does not exist.");
  const LookupResult late = buffer.lookup_transform("base", sec(9), "base", sec(1), "world");
  EXPECT_EQ(late.error, Tf2Error::ForwardExtrapolation) << late.message;
}

TEST(BufferLookup, CanTransformAgreesWithLookup)
{
  BufferCore buffer;
  add_robot(buffer);
  std::string error;
  EXPECT_TRUE(buffer.can_transform("sensor", "hand", sec(5), &error));
  EXPECT_TRUE(buffer.can_transform("sensor", "hand", kLatestTime));
  EXPECT_TRUE(buffer.can_transform("ghost", "ghost", sec(1))); // same name: always
  EXPECT_FALSE(buffer.can_transform("sensor", "hand", sec(6), &error));
  EXPECT_EQ(error,
    "Lookup would require extrapolation at time 6.000000, but only time 5.000000 "
    "is in the buffer, when looking up transform from frame [hand] to frame "
    "[sensor]");
}

// Issue 11.5: frame chains come from the network. Like tf2 (MAX_GRAPH_DEPTH = 1000), a walk
// longer than 1000 frames is reported as a loop instead of costing depth^2 steps per lookup.
TEST(BufferLookup, ChainsDeeperThanTf2AllowsAreReportedAsALoop)
{
  BufferCore buffer;
  const int frames = 1500;
  for (int i = 1; i < frames; ++i)
  {
    ASSERT_TRUE(buffer.set_transform(
      make_stamped("f" + std::to_string(i - 1), "f" + std::to_string(i), sec(1), { 0.001, 0, 0 }),
      "x"));
  }
  const LookupResult within = buffer.lookup_transform("f0", "f1000", sec(1));
  ASSERT_TRUE(within.ok) << within.message.substr(0, 200);
  EXPECT_NEAR(within.transform.translation.x(), 1.0, 1e-9);
  for (TimePoint t : { kLatestTime, sec(1) })
  {
    const LookupResult deep = buffer.lookup_transform("f0", "f1499", t);
    EXPECT_FALSE(deep.ok);
    EXPECT_EQ(deep.error, Tf2Error::Lookup);
    EXPECT_EQ(deep.message.rfind("The tf tree is invalid because it contains a loop.\n", 0), 0u)
      << deep.message.substr(0, 200);
  }
}
