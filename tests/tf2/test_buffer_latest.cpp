// Latest-time lookups (time 0), as a robot's links are looked up at every spin. The buffer
// composes each frame from its parent's pose of the same buffer state instead of walking every
// chain again; these tests hold that to the walker's answers: every latest lookup must equal a
// lookup at the stamp it reports (which samples every link at that time, walking the chain), in
// any order of lookups and after new data.
#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/BufferCore.hpp"

#include <string>
#include <vector>

using namespace tf2test;
using namespace ros2vtk::tf2;

namespace {

/// world ─static─ base ─ l1 ─ l2 ─ l3 ─ l4
///                             └ tool
/// Dynamic links sampled at 1 s and 2 s, except l3 (1 s and 1.5 s): l3 and l4 have the chain
/// time 1.5 s, the others 2 s; l2 -> l3 is interpolated by the ones below it.
void add_arm(BufferCore& buffer)
{
  ASSERT_TRUE(buffer.set_transform(
    make_stamped("world", "base", 0, { 0.5, 0, 0 }, about(0, 0, 1, 30)), "arm", true));
  for (const double t : { 1.0, 2.0 })
  {
    ASSERT_TRUE(buffer.set_transform(
      make_stamped("base", "l1", sec(t), { 0, 0, 0.2 }, about(0, 0, 1, 10 * t)), "arm"));
    ASSERT_TRUE(buffer.set_transform(
      make_stamped("l1", "l2", sec(t), { 0, 0, 0.3 }, about(0, 1, 0, 20 * t)), "arm"));
    ASSERT_TRUE(buffer.set_transform(
      make_stamped("l3", "l4", sec(t), { 0.1 * t, 0, 0.1 }, about(1, 0, 0, 5 * t)), "arm"));
    ASSERT_TRUE(buffer.set_transform(
      make_stamped("l2", "tool", sec(t), { 0, 0.05, 0 }, about(0, 0, 1, -15 * t)), "arm"));
  }
  for (const double t : { 1.0, 1.5 })
  {
    ASSERT_TRUE(buffer.set_transform(
      make_stamped("l2", "l3", sec(t), { 0, 0, 0.25 * t }, about(0, 1, 0, -30 * t)), "arm"));
  }
}

/// The latest lookup of `frame` in `target`, checked against a lookup at the stamp it reports.
void expect_as_walked(const BufferCore& buffer, const std::string& target, const std::string& frame,
  TimePoint expected_stamp)
{
  SCOPED_TRACE(target + " <- " + frame);
  const LookupResult latest = buffer.lookup_transform(target, frame, kLatestTime);
  ASSERT_TRUE(latest.ok) << latest.message;
  EXPECT_EQ(latest.stamp, expected_stamp);
  if (expected_stamp == kLatestTime)
  {
    return; // all static: there is no other time to compare with
  }
  const LookupResult walked = buffer.lookup_transform(target, frame, latest.stamp);
  ASSERT_TRUE(walked.ok) << walked.message;
  EXPECT_TRUE(same_vector(latest.transform.translation, walked.transform.translation, 1e-12));
  EXPECT_TRUE(same_rotation(latest.transform.rotation, walked.transform.rotation, 1e-12));
}

/// The latest lookup of `frame` in world, on a chain without rotations: its stamp and offset.
void expect_latest_offset(const BufferCore& buffer, const std::string& frame,
  TimePoint expected_stamp, const Eigen::Vector3d& expected_offset)
{
  SCOPED_TRACE("world <- " + frame);
  const LookupResult latest = buffer.lookup_transform("world", frame, kLatestTime);
  ASSERT_TRUE(latest.ok) << latest.message;
  EXPECT_EQ(latest.stamp, expected_stamp);
  EXPECT_TRUE(same_vector(latest.transform.translation, expected_offset));
}

struct Expected
{
  std::string frame;
  TimePoint stamp;
};

} // namespace

TEST(BufferLatest, EveryLinkAgreesWithTheWalkAtItsStampInAnyOrder)
{
  const std::vector<Expected> links = { { "base", kLatestTime }, { "l1", sec(2) }, { "l2", sec(2) },
    { "l3", sec(1.5) }, { "l4", sec(1.5) }, { "tool", sec(2) } };
  for (const bool leaves_first : { false, true })
  {
    SCOPED_TRACE(leaves_first ? "leaves first" : "root first");
    BufferCore buffer;
    add_arm(buffer);
    std::vector<Expected> order = links;
    if (leaves_first)
    {
      order.assign(links.rbegin(), links.rend());
    }
    for (int round = 0; round < 2; ++round) // the second round reads what the first remembered
    {
      for (const Expected& link : order)
      {
        expect_as_walked(buffer, "world", link.frame, link.stamp);
      }
    }
    // New data for l1 only: l1's chain moves to 3 s, l2's stays at its own newest (2 s).
    ASSERT_TRUE(buffer.set_transform(
      make_stamped("base", "l1", sec(3), { 0, 0, 0.2 }, about(0, 0, 1, 30)), "arm"));
    for (const Expected& link : order)
    {
      const TimePoint stamp = link.frame == "l1" ? sec(3) : link.stamp;
      expect_as_walked(buffer, "world", link.frame, stamp);
    }
    // A target inside the chain, and one that is not an ancestor (the walker's case).
    expect_as_walked(buffer, "l1", "l4", sec(1.5));
    expect_as_walked(buffer, "l4", "tool", sec(1.5));
  }
}

TEST(BufferLatest, TheWorldPoseOfTheLastLinkIsTheHandComputedOne)
{
  // Translations only, so the answer is a sum: base (1,0,0) static, l1 (0,2,0) at 1 s and
  // (0,4,0) at 3 s, l2 (0,0,1) at 2 s only. Chain time of l2: 2 s, where l1 is (0,3,0).
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", 0, { 1, 0, 0 }), "x", true));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "l1", sec(1), { 0, 2, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "l1", sec(3), { 0, 4, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("l1", "l2", sec(2), { 0, 0, 1 }), "x"));
  expect_latest_offset(buffer, "l1", sec(3), { 1, 4, 0 });
  expect_latest_offset(buffer, "l2", sec(2), { 1, 3, 1 });
}

TEST(BufferLatest, AParentChangedWithinTheHistoryIsFollowedAtTheChainTime)
{
  // x hangs under a at 1 s and under b at 2 s; y under x has only 1 s: its chain goes through a.
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "a", 0, { 1, 0, 0 }), "x", true));
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "b", 0, { 0, 1, 0 }), "x", true));
  ASSERT_TRUE(buffer.set_transform(make_stamped("a", "x", sec(1), { 0, 0, 1 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("b", "x", sec(2), { 0, 0, 2 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("x", "y", sec(1), { 0, 0, 3 }), "x"));
  expect_latest_offset(buffer, "x", sec(2), { 0, 1, 2 });
  expect_latest_offset(buffer, "y", sec(1), { 1, 0, 4 });
}

TEST(BufferLatest, ErrorsDoNotDependOnWhatWasLookedUpBefore)
{
  // l1 keeps 10 s of history (11 .. 21 s); l2 has one sample at 5 s, older than all of it.
  auto fill = [](BufferCore& buffer) {
    for (int t = 1; t <= 21; ++t)
    {
      ASSERT_TRUE(buffer.set_transform(make_stamped("base", "l1", sec(t), { 0, 0, 1 }), "x"));
    }
    ASSERT_TRUE(buffer.set_transform(make_stamped("l1", "l2", sec(5), { 0, 0, 1 }), "x"));
  };
  BufferCore fresh;
  fill(fresh);
  const LookupResult alone = fresh.lookup_transform("base", "l2", kLatestTime);
  BufferCore warmed;
  fill(warmed);
  ASSERT_TRUE(warmed.lookup_transform("base", "l1", kLatestTime).ok);
  const LookupResult after_parent = warmed.lookup_transform("base", "l2", kLatestTime);
  EXPECT_FALSE(alone.ok);
  EXPECT_EQ(alone.error, Tf2Error::BackwardExtrapolation) << alone.message;
  EXPECT_EQ(after_parent.error, alone.error);
  EXPECT_EQ(after_parent.message, alone.message);
}

TEST(BufferLatest, TheDepthBoundHoldsWhenChainsAreComposedFromRememberedParents)
{
  BufferCore buffer;
  for (int i = 1; i <= 1001; ++i)
  {
    ASSERT_TRUE(buffer.set_transform(
      make_stamped("f" + std::to_string(i - 1), "f" + std::to_string(i), sec(1), { 0.001, 0, 0 }),
      "x"));
  }
  // f1000 is 1000 links below f0 (tf2's limit), f1001 one more: a "loop" for tf2.
  const LookupResult within = buffer.lookup_transform("f0", "f1000", kLatestTime);
  ASSERT_TRUE(within.ok) << within.message.substr(0, 200);
  EXPECT_NEAR(within.transform.translation.x(), 1.0, 1e-9);
  const LookupResult deep = buffer.lookup_transform("f0", "f1001", kLatestTime);
  EXPECT_FALSE(deep.ok);
  EXPECT_EQ(deep.error, Tf2Error::Lookup);
  EXPECT_EQ(deep.message.rfind("The tf tree is invalid because it contains a loop.\n", 0), 0u)
    << deep.message.substr(0, 200);
}

// A lookup node reuses one result at every spin; the result remembers the frame ids its names
// resolved to. The remembered ids must follow the names and the buffer: a result reused for
// other names, or with another buffer that numbered its frames differently, must answer for
// what it is asked, as a fresh result does.
TEST(BufferLatest, AReusedResultAnswersForTheNamesAndTheBufferItIsGiven)
{
  BufferCore arm;
  add_arm(arm);
  // The same frame names, interned in another order: other ids for "l2" and "tool".
  BufferCore other;
  ASSERT_TRUE(other.set_transform(make_stamped("l2", "tool", sec(1), { 1, 2, 3 }), "other", true));
  ASSERT_TRUE(
    other.set_transform(make_stamped("world", "l2", sec(1), { 10, 0, 0 }), "other", true));

  auto expect_same = [](const LookupResult& reused, const LookupResult& fresh) {
    EXPECT_EQ(reused.ok, fresh.ok);
    EXPECT_EQ(reused.error, fresh.error);
    EXPECT_EQ(reused.message, fresh.message);
    EXPECT_EQ(reused.target_frame, fresh.target_frame);
    EXPECT_EQ(reused.source_frame, fresh.source_frame);
    EXPECT_EQ(reused.stamp, fresh.stamp);
    // Bit for bit: both come from the same walk of the same data.
    EXPECT_TRUE(
      (reused.transform.translation.array() == fresh.transform.translation.array()).all());
    EXPECT_TRUE(
      (reused.transform.rotation.coeffs().array() == fresh.transform.rotation.coeffs().array())
        .all());
  };
  LookupResult reused;
  for (int spin = 0; spin < 2; ++spin) // the second time from the remembered ids
  {
    SCOPED_TRACE("spin " + std::to_string(spin));
    arm.lookup_transform("world", "tool", kLatestTime, reused);
    ASSERT_TRUE(reused.ok) << reused.message;
    expect_same(reused, arm.lookup_transform("world", "tool", kLatestTime));
  }
  // Other names into the same result.
  arm.lookup_transform("world", "l4", kLatestTime, reused);
  expect_same(reused, arm.lookup_transform("world", "l4", kLatestTime));
  arm.lookup_transform("l1", "l4", sec(1.25), reused);
  expect_same(reused, arm.lookup_transform("l1", "l4", sec(1.25)));
  // The same names with another buffer: world <- tool there is (10, 0, 0) + (1, 2, 3).
  arm.lookup_transform("world", "tool", kLatestTime, reused);
  other.lookup_transform("world", "tool", kLatestTime, reused);
  ASSERT_TRUE(reused.ok) << reused.message;
  EXPECT_TRUE(same_vector(reused.transform.translation, Eigen::Vector3d(11, 2, 3), 1e-12));
  expect_same(reused, other.lookup_transform("world", "tool", kLatestTime));
  // An unknown name after a resolved one fails as a fresh lookup does, then recovers.
  arm.lookup_transform("world", "tool", kLatestTime, reused);
  arm.lookup_transform("world", "nowhere", kLatestTime, reused);
  EXPECT_FALSE(reused.ok);
  expect_same(reused, arm.lookup_transform("world", "nowhere", kLatestTime));
  arm.lookup_transform("world", "tool", kLatestTime, reused);
  expect_same(reused, arm.lookup_transform("world", "tool", kLatestTime));
  // New data after the ids were remembered: the answer moves with it.
  ASSERT_TRUE(arm.set_transform(
    make_stamped("l2", "tool", sec(3), { 0, 0.5, 0 }, about(0, 0, 1, 45)), "arm"));
  arm.lookup_transform("world", "tool", kLatestTime, reused);
  expect_same(reused, arm.lookup_transform("world", "tool", kLatestTime));
}
