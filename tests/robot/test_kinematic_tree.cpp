// Kinematics from URDF, checked against poses computed by hand.
#include "ros2vtk/robot/KinematicTree.hpp"

#include <gtest/gtest.h>

#include "chain_urdf.hpp"

#include <cmath>

using ros2vtk::robot::KinematicTree;

namespace {

// base --(fixed, z+0.1)--> column --(revolute about z, x+0.5)--> arm
//      --(prismatic along x, rpy yaw 90°)--> slider --(revolute, mimic of shoulder *2 +0.1)--> tip
const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="test_arm">
  <link name="base"/><link name="column"/><link name="arm"/><link name="slider"/><link name="tip"/>
  <joint name="mount" type="fixed"><parent link="base"/><child link="column"/>
    <origin xyz="0 0 0.1" rpy="0 0 0"/></joint>
  <joint name="shoulder" type="revolute"><parent link="column"/><child link="arm"/>
    <origin xyz="0.5 0 0" rpy="0 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-1.5" upper="1.5" effort="1" velocity="1"/></joint>
  <joint name="insertion" type="prismatic"><parent link="arm"/><child link="slider"/>
    <origin xyz="0 0 0" rpy="0 0 1.5707963267948966"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.2" effort="1" velocity="1"/></joint>
  <joint name="wrist" type="revolute"><parent link="slider"/><child link="tip"/>
    <origin xyz="0 0 0" rpy="0 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/>
    <mimic joint="shoulder" multiplier="2" offset="0.1"/></joint>
</robot>)";

} // namespace

TEST(KinematicTree, ParsesJointsInParentFirstOrder)
{
  std::string error;
  auto tree = KinematicTree::from_urdf(kUrdf, &error);
  ASSERT_TRUE(tree) << error;
  EXPECT_EQ(tree->robot_name(), "test_arm");
  EXPECT_EQ(tree->root_link(), "base");
  ASSERT_EQ(tree->joints().size(), 4u);
  EXPECT_EQ(tree->joints()[0].name, "mount");
  EXPECT_EQ(tree->joints()[3].name, "wrist");
  EXPECT_EQ(tree->actuated_joints(), (std::vector<std::string>{ "shoulder", "insertion" }));
}

TEST(KinematicTree, LinkPosesMatchHandComputation)
{
  std::string error;
  auto tree = KinematicTree::from_urdf(kUrdf, &error);
  ASSERT_TRUE(tree) << error;
  const double shoulder = M_PI / 2; // arm rotated 90° about z
  const double insertion = 0.05;
  auto poses = tree->link_poses({ { "shoulder", shoulder }, { "insertion", insertion } });
  // column: (0, 0, 0.1); arm: column + (0.5, 0, 0), rotated 90° about z.
  EXPECT_NEAR(poses["arm"].translation().x(), 0.5, 1e-12);
  EXPECT_NEAR(poses["arm"].translation().z(), 0.1, 1e-12);
  // slider frame: arm frame yawed another 90° (total 180°), then moved 0.05 along its own x,
  // which points along world -x.
  EXPECT_NEAR(poses["slider"].translation().x(), 0.5 - 0.05, 1e-12);
  EXPECT_NEAR(poses["slider"].translation().y(), 0.0, 1e-12);
  // tip: mimic 2 * 90° + 0.1 rad on top of the slider's 180° -> total yaw 360° + 0.1 rad.
  const Eigen::Matrix3d r = poses["tip"].linear();
  EXPECT_NEAR(r(0, 0), std::cos(0.1), 1e-12);
  EXPECT_NEAR(r(1, 0), std::sin(0.1), 1e-12);
}

TEST(KinematicTree, FixedJointsAreStaticTransforms)
{
  std::string error;
  auto tree = KinematicTree::from_urdf(kUrdf, &error);
  ASSERT_TRUE(tree) << error;
  auto transforms = tree->joint_transforms({});
  ASSERT_EQ(transforms.size(), 4u);
  EXPECT_TRUE(transforms[0].is_static);
  EXPECT_EQ(transforms[0].parent, "base");
  EXPECT_EQ(transforms[0].child, "column");
  EXPECT_FALSE(transforms[1].is_static);
}

TEST(KinematicTree, RejectsBrokenUrdfWithAMessage)
{
  std::string error;
  EXPECT_FALSE(KinematicTree::from_urdf("", &error));
  EXPECT_EQ(error, "URDF is empty");
  EXPECT_FALSE(
    KinematicTree::from_urdf("<robot name='x'><joint name='j' type='fixed'><parent link='a'/>"
                             "<child link='b'/></joint></robot>",
      &error));
  EXPECT_NE(error.find("URDF failed to parse"), std::string::npos);
  EXPECT_FALSE(KinematicTree::from_urdf("<robot", &error));
}

// Issue 11.2: the joint walk recursed once per link; a 10 000-link chain from the network
// overflowed the stack.
TEST(KinematicTree, ChainOfTenThousandLinksIsWalkedParentFirst)
{
  const int links = 10000;
  std::string error;
  auto tree = KinematicTree::from_urdf(ros2vtk_test::chain_urdf(links), &error);
  ASSERT_TRUE(tree) << error;
  const auto names = tree->link_names();
  ASSERT_EQ(names.size(), static_cast<size_t>(links));
  EXPECT_EQ(names.front(), "link_9999");
  EXPECT_EQ(names.back(), "link_0");
  const auto poses = tree->link_poses({});
  ASSERT_EQ(poses.size(), static_cast<size_t>(links));
  EXPECT_NEAR(poses.at("link_0").translation().z(), 9.999, 1e-9); // 9999 joints of 1 mm
}

TEST(KinematicTree, LinkReachBoundsEveryPose)
{
  std::string error;
  auto tree = KinematicTree::from_urdf(kUrdf, &error);
  ASSERT_TRUE(tree) << error;
  const auto reach = tree->link_reach();
  // By hand: column fixed at (0, 0, 0.1); arm's origin stays at (0.5, 0, 0.1) (the shoulder
  // turns about its own origin); the slider moves up to 0.2 from there; the tip with it.
  auto expect = [&](const char* link, Eigen::Vector3d centre, double radius) {
    EXPECT_NEAR((reach.at(link).centre - centre).norm(), 0.0, 1e-12) << link;
    EXPECT_NEAR(reach.at(link).radius, radius, 1e-12) << link;
  };
  expect("base", { 0, 0, 0 }, 0.0);
  expect("column", { 0, 0, 0.1 }, 0.0);
  expect("arm", { 0.5, 0, 0.1 }, 0.0);
  expect("slider", { 0.5, 0, 0.1 }, 0.2);
  expect("tip", { 0.5, 0, 0.1 }, 0.2);
  // No pose over a grid of the joints' ranges puts a link's origin outside its ball.
  for (double shoulder = -1.5; shoulder <= 1.5; shoulder += 0.25)
  {
    for (double insertion = 0.0; insertion <= 0.2; insertion += 0.05)
    {
      for (const auto& [link, pose] :
        tree->link_poses({ { "shoulder", shoulder }, { "insertion", insertion } }))
      {
        EXPECT_LE(
          (pose.translation() - reach.at(link).centre).norm(), reach.at(link).radius + 1e-12)
          << link;
      }
    }
  }
}

TEST(KinematicTree, LinkReachOfAnArmOnAColumnStartsAtItsShoulder)
{
  // A column turning about z with the shoulder on that axis: the shoulder stays in place, so the
  // arm's links are within the arm's length of it (not of the base).
  const char* urdf = R"(<?xml version="1.0"?>
<robot name="column_arm">
  <link name="base"/><link name="column"/><link name="upper"/><link name="fore"/>
  <joint name="turn" type="revolute"><parent link="base"/><child link="column"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="shoulder" type="revolute"><parent link="column"/><child link="upper"/>
    <origin xyz="0 0 0.4"/><axis xyz="0 1 0"/><limit lower="-1.6" upper="1.6" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.35"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
</robot>)";
  std::string error;
  auto tree = KinematicTree::from_urdf(urdf, &error);
  ASSERT_TRUE(tree) << error;
  const auto reach = tree->link_reach();
  EXPECT_NEAR((reach.at("upper").centre - Eigen::Vector3d(0, 0, 0.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(reach.at("upper").radius, 0.0, 1e-12);
  EXPECT_NEAR((reach.at("fore").centre - Eigen::Vector3d(0, 0, 0.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(reach.at("fore").radius, 0.35, 1e-12);
  for (double turn = -3; turn <= 3; turn += 0.5)
  {
    for (double shoulder = -1.6; shoulder <= 1.6; shoulder += 0.4)
    {
      for (const auto& [link, pose] :
        tree->link_poses({ { "turn", turn }, { "shoulder", shoulder }, { "elbow", 1.0 } }))
      {
        EXPECT_LE((pose.translation() - reach.at(link).centre).norm(), reach.at(link).radius + 1e-9)
          << link;
      }
    }
  }
}
