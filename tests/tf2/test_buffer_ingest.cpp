// setTransform: validation ids, slash stripping, quaternion tolerance, cache kind switching.
#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/BufferCore.hpp"

#include <limits>

using namespace tf2test;
using namespace ros2vtk::tf2;

namespace {

bool starts_with(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}

} // namespace

TEST(BufferIngest, AcceptsAValidTransform)
{
  BufferCore buffer;
  std::string error = "untouched";
  EXPECT_TRUE(buffer.set_transform(
    make_stamped("world", "base", sec(1), { 1, 2, 3 }), "test", false, &error));
  EXPECT_EQ(error, "untouched");
  EXPECT_TRUE(buffer.frame_exists("world"));
  EXPECT_TRUE(buffer.frame_exists("base"));
}

TEST(BufferIngest, RejectsSelfTransform)
{
  BufferCore buffer;
  std::string error;
  EXPECT_FALSE(buffer.set_transform(
    make_stamped("base", "base", sec(1), { 0, 0, 0 }), "robot", false, &error));
  EXPECT_EQ(error,
    "TF_SELF_TRANSFORM: Ignoring transform from authority \"robot\" with frame_id "
    "and child_frame_id \"base\" because they are the same");
  EXPECT_FALSE(buffer.frame_exists("base"));
  // "/base" and "base" are the same frame once the slash is stripped.
  EXPECT_FALSE(buffer.set_transform(
    make_stamped("/base", "base", sec(1), { 0, 0, 0 }), "robot", false, &error));
  EXPECT_TRUE(starts_with(error, "TF_SELF_TRANSFORM:")) << error;
}

TEST(BufferIngest, RejectsMissingFrameIds)
{
  BufferCore buffer;
  std::string error;
  EXPECT_FALSE(
    buffer.set_transform(make_stamped("world", "", sec(1), { 0, 0, 0 }), "a", false, &error));
  EXPECT_EQ(error,
    "TF_NO_CHILD_FRAME_ID: Ignoring transform from authority \"a\" because "
    "child_frame_id not set");
  EXPECT_FALSE(
    buffer.set_transform(make_stamped("", "base", sec(1), { 0, 0, 0 }), "a", false, &error));
  EXPECT_EQ(error,
    "TF_NO_FRAME_ID: Ignoring transform with child_frame_id \"base\" from "
    "authority \"a\" because frame_id not set");
  // A lone "/" is empty after stripping.
  EXPECT_FALSE(
    buffer.set_transform(make_stamped("/", "base", sec(1), { 0, 0, 0 }), "a", false, &error));
  EXPECT_TRUE(starts_with(error, "TF_NO_FRAME_ID:")) << error;
  EXPECT_TRUE(buffer.all_frame_names().empty());
}

TEST(BufferIngest, ReportsEveryProblemOfOneTransform)
{
  BufferCore buffer;
  std::string error;
  // Both ids empty: the same (self transform), child missing and parent missing, like tf2.
  EXPECT_FALSE(buffer.set_transform(make_stamped("", "", sec(1), { 0, 0, 0 }), "a", false, &error));
  EXPECT_NE(error.find("TF_SELF_TRANSFORM:"), std::string::npos) << error;
  EXPECT_NE(error.find("\nTF_NO_CHILD_FRAME_ID:"), std::string::npos) << error;
  EXPECT_NE(error.find("\nTF_NO_FRAME_ID:"), std::string::npos) << error;
}

TEST(BufferIngest, RejectsNaN)
{
  BufferCore buffer;
  std::string error;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(
    buffer.set_transform(make_stamped("world", "base", sec(1), { 1, nan, 3 }), "a", false, &error));
  EXPECT_EQ(error,
    "TF_NAN_INPUT: Ignoring transform for child_frame_id \"base\" from authority "
    "\"a\" because of a nan value in the transform (1.000000 nan 3.000000) "
    "(0.000000 0.000000 0.000000 1.000000)");
  EXPECT_FALSE(buffer.frame_exists("base"));

  // NaN in the quaternion also makes it denormalised: both lines, as tf2 logs both.
  EXPECT_FALSE(buffer.set_transform(
    make_stamped("world", "base", sec(1), { 0, 0, 0 }, Eigen::Quaterniond(nan, 0, 0, 0)), "a",
    false, &error));
  EXPECT_TRUE(starts_with(error, "TF_NAN_INPUT:")) << error;
  EXPECT_NE(error.find("\nTF_DENORMALIZED_QUATERNION:"), std::string::npos) << error;
}

TEST(BufferIngest, RejectsInfinity)
{
  BufferCore buffer;
  std::string error;
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(
    buffer.set_transform(make_stamped("world", "base", sec(1), { inf, 0, 0 }), "a", false, &error));
  EXPECT_TRUE(starts_with(error, "TF_NAN_INPUT:")) << error;
  EXPECT_NE(error.find("infinite"), std::string::npos) << error;
}

TEST(BufferIngest, QuaternionToleranceIsOneHundredthOnTheSquaredNorm)
{
  BufferCore buffer;
  std::string error;
  // |q|^2 = 1.006^2 = 1.012036: off by more than 0.01 -> rejected.
  EXPECT_FALSE(buffer.set_transform(
    make_stamped("world", "a", sec(1), { 0, 0, 0 }, Eigen::Quaterniond(1.006, 0, 0, 0)), "x", false,
    &error));
  EXPECT_EQ(error,
    "TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id \"a\" from "
    "authority \"x\" because of an invalid quaternion in the transform "
    "(0.000000 0.000000 0.000000 1.006000)");
  // |q|^2 = 0.995^2 = 0.990025: off by 0.009975 -> accepted.
  EXPECT_TRUE(buffer.set_transform(
    make_stamped("world", "b", sec(1), { 0, 0, 0 }, Eigen::Quaterniond(0.995, 0, 0, 0)), "x"));
  // The zero quaternion is as far off as it gets.
  EXPECT_FALSE(buffer.set_transform(
    make_stamped("world", "c", sec(1), { 0, 0, 0 }, Eigen::Quaterniond(0, 0, 0, 0)), "x"));
}

TEST(BufferIngest, NormalisesAnAcceptedQuaternion)
{
  BufferCore buffer;
  // (0, 0, 0.6, 0.8) scaled by 1.004: |q|^2 = 1.008016, accepted and stored as (0, 0, 0.6, 0.8).
  const Eigen::Quaterniond scaled(0.8 * 1.004, 0, 0, 0.6 * 1.004);
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "a", sec(1), { 0, 0, 0 }, scaled), "x"));
  const LookupResult r = buffer.lookup_transform("world", "a", sec(1));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.transform.rotation.z(), 0.6, 1e-12);
  EXPECT_NEAR(r.transform.rotation.w(), 0.8, 1e-12);
  EXPECT_NEAR(r.transform.rotation.norm(), 1.0, 1e-12);
}

TEST(BufferIngest, StripsExactlyOneLeadingSlash)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("/world", "/base", sec(1), { 1, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "//tool", sec(1), { 1, 0, 0 }), "x"));
  EXPECT_TRUE(buffer.frame_exists("world"));
  EXPECT_TRUE(buffer.frame_exists("base"));
  EXPECT_FALSE(buffer.frame_exists("/base"));
  EXPECT_TRUE(buffer.frame_exists("/tool")); // only one slash goes
  EXPECT_TRUE(buffer.lookup_transform("world", "base", sec(1)).ok);
}

TEST(BufferIngest, RefusesOldDataWithTf2Message)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(20), { 0, 0, 0 }), "x"));
  std::string error;
  EXPECT_FALSE(buffer.set_transform(
    make_stamped("world", "base", sec(5), { 0, 0, 0 }), "late", false, &error));
  EXPECT_EQ(error,
    "TF_OLD_DATA ignoring data from the past for frame base at time 5.000000 "
    "according to authority late\nPossible reasons are listed at "
    "http://wiki.ros.org/tf/Errors%20explained");
  // The same old stamp is fine for a static transform: it replaces the cache.
  EXPECT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(5), { 0, 0, 0 }), "s", true));
}

TEST(BufferIngest, ShorterCacheTimeIsHonoured)
{
  BufferCore buffer(sec(1));
  EXPECT_EQ(buffer.cache_time(), sec(1));
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(5), { 0, 0, 0 }), "x"));
  EXPECT_FALSE(buffer.set_transform(make_stamped("world", "base", sec(3.9), { 0, 0, 0 }), "x"));
  EXPECT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(4), { 0, 0, 0 }), "x"));
}

TEST(BufferIngest, StaticAndDynamicDataReplaceEachOther)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "cam", sec(1), { 1, 0, 0 }), "d"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "cam", sec(2), { 2, 0, 0 }), "d"));
  // Static now: valid at every time, including long after the dynamic samples.
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "cam", sec(0), { 5, 0, 0 }), "s", true));
  LookupResult r = buffer.lookup_transform("world", "cam", sec(100));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_DOUBLE_EQ(r.transform.translation.x(), 5.0);
  // Dynamic again: history restarts from this one sample.
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "cam", sec(3), { 3, 0, 0 }), "d"));
  r = buffer.lookup_transform("world", "cam", sec(100));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error, Tf2Error::NoDataForExtrapolation);
  r = buffer.lookup_transform("world", "cam", sec(3));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_DOUBLE_EQ(r.transform.translation.x(), 3.0);
}
