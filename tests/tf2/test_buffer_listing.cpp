// Frame listings: names, the "exists with parent" string and the YAML-ish overview.
#include "Tf2TestUtil.hpp"

#include "ros2vtk/tf2/BufferCore.hpp"

using namespace tf2test;
using namespace ros2vtk::tf2;

TEST(BufferListing, FrameNamesInOrderOfAppearance)
{
  BufferCore buffer;
  EXPECT_TRUE(buffer.all_frame_names().empty());
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(1), { 0, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "arm", sec(1), { 0, 0, 0 }), "x"));
  // Child first, then parent, as they are interned.
  EXPECT_EQ(buffer.all_frame_names(), (std::vector<std::string>{ "base", "world", "arm" }));
}

TEST(BufferListing, AllFramesAsString)
{
  BufferCore buffer;
  EXPECT_EQ(buffer.all_frames_as_string(), "");
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(1), { 0, 0, 0 }), "x"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("base", "arm", sec(1), { 0, 0, 0 }), "x", true));
  EXPECT_EQ(buffer.all_frames_as_string(),
    "Frame base exists with parent world.\nFrame arm exists with parent base.\n");
}

TEST(BufferListing, AllFramesAsYaml)
{
  BufferCore buffer;
  EXPECT_EQ(buffer.all_frames_as_yaml(), "[]");
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(1), { 0, 0, 0 }), "robot_a"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "base", sec(3), { 0, 0, 0 }), "robot_b"));
  // Two samples over 2 s: rate 1.000 Hz, buffer length 2.000 s; delay to 3.5 s: 0.500 s.
  EXPECT_EQ(buffer.all_frames_as_yaml(sec(3.5)),
    "base:\n"
    "  parent: 'world'\n"
    "  broadcaster: 'robot_b'\n"
    "  rate: 1.000\n"
    "  most_recent_transform: 3.000000\n"
    "  oldest_transform: 1.000000\n"
    "  transform_delay: 0.500\n"
    "  buffer_length: 2.000\n");
  // Without a current time there is no delay line.
  EXPECT_EQ(buffer.all_frames_as_yaml().find("transform_delay"), std::string::npos);
}

// A listener that learns a sender's node only after inserting its transforms (a latched
// /tf_static message arrives before the node's announcement) names it afterwards; a frame that
// another sender has set since keeps that sender's name.
TEST(BufferListing, AnAuthorityLearntLaterReplacesThePlaceholderOnly)
{
  BufferCore buffer;
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "camera", 0, { 0, 0, 1 }), "?", true));
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "tool", sec(1), { 0, 0, 0 }), "?"));
  ASSERT_TRUE(buffer.set_transform(make_stamped("world", "tool", sec(2), { 0, 0, 0 }), "/arm"));
  buffer.replace_authority("camera", "?", "/camera_mount");
  buffer.replace_authority("tool", "?", "/camera_mount");
  buffer.replace_authority("nowhere", "?", "/camera_mount"); // unknown frame: nothing happens
  const std::string yaml = buffer.all_frames_as_yaml();
  EXPECT_NE(
    yaml.find("camera:\n  parent: 'world'\n  broadcaster: '/camera_mount'\n"), std::string::npos)
    << yaml;
  EXPECT_NE(yaml.find("tool:\n  parent: 'world'\n  broadcaster: '/arm'\n"), std::string::npos)
    << yaml;
  EXPECT_FALSE(buffer.frame_exists("nowhere"));
}
