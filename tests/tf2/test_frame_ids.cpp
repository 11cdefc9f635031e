#include <gtest/gtest.h>

#include "ros2vtk/tf2/FrameIds.hpp"

using namespace ros2vtk::tf2;

TEST(FrameIds, InternsOncePerName)
{
  FrameIds ids;
  const FrameId world = ids.intern("world");
  const FrameId base = ids.intern("base");
  EXPECT_NE(world, kNoFrame);
  EXPECT_NE(base, kNoFrame);
  EXPECT_NE(world, base);
  EXPECT_EQ(ids.intern("world"), world);
  EXPECT_EQ(ids.find("base"), base);
  EXPECT_EQ(ids.name(world), "world");
  EXPECT_EQ(ids.size(), 3u);
}

TEST(FrameIds, UnknownNamesAndIds)
{
  FrameIds ids;
  EXPECT_EQ(ids.find("nowhere"), kNoFrame);
  EXPECT_EQ(ids.name(kNoFrame), "NO_PARENT");
  EXPECT_EQ(ids.name(42), "NO_PARENT");
  // A frame literally called NO_PARENT is an ordinary frame, not the "no frame" id.
  EXPECT_NE(ids.intern("NO_PARENT"), kNoFrame);
}
