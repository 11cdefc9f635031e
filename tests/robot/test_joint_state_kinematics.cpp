// Joint positions -> link poses (issue 15): zero configuration, limits, continuous joints, mimic
// joints and JointState checks, against poses worked out by hand in the comments.
#include "ros2vtk/robot/JointStateKinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using ros2vtk::robot::JointStateKinematics;
using SetResult = JointStateKinematics::SetResult;

namespace {

// base --fixed (0, 0, 0.1)--> column
// column --revolute about z at (0.5, 0, 0), limits [-2, 2]--> arm
// arm --prismatic along x, limits [0.05, 0.2]--> slider
// arm --continuous about z at (0, 0.2, 0)--> wheel
// slider --revolute about z at (0.1, 0, 0), mimic shoulder * -2 + 0.1, limits [-0.5, 0.5]--> jaw
// slider --revolute about z, mimic jaw * 0.5--> jaw_follower (a mimic of a mimic)
const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="fk_test">
  <link name="base"/><link name="column"/><link name="arm"/><link name="slider"/><link name="wheel"/>
  <link name="jaw"/><link name="jaw_follower"/>
  <joint name="mount" type="fixed"><parent link="base"/><child link="column"/>
    <origin xyz="0 0 0.1"/></joint>
  <joint name="shoulder" type="revolute"><parent link="column"/><child link="arm"/>
    <origin xyz="0.5 0 0"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="insertion" type="prismatic"><parent link="arm"/><child link="slider"/>
    <axis xyz="1 0 0"/><limit lower="0.05" upper="0.2" effort="1" velocity="1"/></joint>
  <joint name="spin" type="continuous"><parent link="arm"/><child link="wheel"/>
    <origin xyz="0 0.2 0"/><axis xyz="0 0 1"/></joint>
  <joint name="grip" type="revolute"><parent link="slider"/><child link="jaw"/>
    <origin xyz="0.1 0 0"/><axis xyz="0 0 1"/><limit lower="-0.5" upper="0.5" effort="1" velocity="1"/>
    <mimic joint="shoulder" multiplier="-2" offset="0.1"/></joint>
  <joint name="grip_follower" type="revolute"><parent link="slider"/><child link="jaw_follower"/>
    <axis xyz="0 0 1"/><limit lower="-5" upper="5" effort="1" velocity="1"/>
    <mimic joint="grip" multiplier="0.5"/></joint>
</robot>)";

constexpr double kTolerance = 1e-12;

std::unique_ptr<JointStateKinematics> make()
{
  std::string error;
  auto kinematics = JointStateKinematics::from_urdf(kUrdf, &error);
  EXPECT_TRUE(kinematics) << error;
  return kinematics;
}

void expect_position(const Eigen::Isometry3d& pose, double x, double y, double z)
{
  EXPECT_NEAR(pose.translation().x(), x, kTolerance);
  EXPECT_NEAR(pose.translation().y(), y, kTolerance);
  EXPECT_NEAR(pose.translation().z(), z, kTolerance);
}

/// The pose's rotation is a rotation of `yaw` radians about z.
void expect_yaw(const Eigen::Isometry3d& pose, double yaw)
{
  const Eigen::Matrix3d r = pose.linear();
  const double expected[3][3] = { { std::cos(yaw), -std::sin(yaw), 0 },
    { std::sin(yaw), std::cos(yaw), 0 }, { 0, 0, 1 } };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(r(i, j), expected[i][j], kTolerance) << "element " << i << "," << j;
}

} // namespace

TEST(JointStateKinematics, JointNamesAreTheActuatedJointsInTreeOrder)
{
  auto kinematics = make();
  ASSERT_TRUE(kinematics);
  EXPECT_EQ(
    kinematics->joint_names(), (std::vector<std::string>{ "shoulder", "insertion", "spin" }));
  EXPECT_FALSE(kinematics->has_positions());
}

TEST(JointStateKinematics, ZeroConfigurationIsZeroClampedIntoLimits)
{
  auto kinematics = make();
  ASSERT_TRUE(kinematics);
  // insertion's range [0.05, 0.2] does not hold 0: it starts at 0.05.
  EXPECT_EQ(kinematics->position("insertion"), 0.05);
  EXPECT_EQ(kinematics->position("shoulder"), 0.0);
  EXPECT_NEAR(kinematics->position("grip"), 0.1, kTolerance); // -2 * 0 + 0.1
  auto poses = kinematics->link_poses();
  ASSERT_EQ(poses.size(), 7u);
  expect_position(poses.at("base"), 0, 0, 0);
  expect_position(poses.at("column"), 0, 0, 0.1);
  expect_position(poses.at("arm"), 0.5, 0, 0.1);
  expect_position(poses.at("slider"), 0.55, 0, 0.1);
  expect_position(poses.at("wheel"), 0.5, 0.2, 0.1);
  expect_position(poses.at("jaw"), 0.65, 0, 0.1);
  expect_yaw(poses.at("jaw"), 0.1);
  expect_yaw(poses.at("jaw_follower"), 0.05);
}

TEST(JointStateKinematics, RevolutePrismaticContinuousAndMimicJoints)
{
  auto kinematics = make();
  ASSERT_TRUE(kinematics);
  EXPECT_EQ(kinematics->set_position("shoulder", M_PI / 2), SetResult::Applied);
  EXPECT_EQ(kinematics->set_position("insertion", 0.15), SetResult::Applied);
  EXPECT_EQ(kinematics->set_position("spin", 7.0), SetResult::Applied); // continuous: beyond 2 pi
  EXPECT_TRUE(kinematics->has_positions());
  auto poses = kinematics->link_poses();
  // arm at (0.5, 0, 0.1) yawed 90°: its x is the world's y.
  expect_position(poses.at("arm"), 0.5, 0, 0.1);
  expect_yaw(poses.at("arm"), M_PI / 2);
  // slider: 0.15 along the arm's x = world +y.
  expect_position(poses.at("slider"), 0.5, 0.15, 0.1);
  expect_yaw(poses.at("slider"), M_PI / 2);
  // wheel: (0, 0.2, 0) in the arm's frame = world -x; yawed 90° + 7 rad.
  expect_position(poses.at("wheel"), 0.3, 0, 0.1);
  expect_yaw(poses.at("wheel"), M_PI / 2 + 7.0);
  // jaw: 0.1 further along world +y; grip = -2 * pi/2 + 0.1 = -pi + 0.1, beyond its own limit
  // of -0.5: a mimic joint follows its leader exactly.
  EXPECT_NEAR(kinematics->position("grip"), -M_PI + 0.1, kTolerance);
  expect_position(poses.at("jaw"), 0.5, 0.25, 0.1);
  expect_yaw(poses.at("jaw"), M_PI / 2 - M_PI + 0.1);
  // jaw_follower: half of grip, on the slider's origin.
  EXPECT_NEAR(kinematics->position("grip_follower"), 0.5 * (-M_PI + 0.1), kTolerance);
  expect_position(poses.at("jaw_follower"), 0.5, 0.15, 0.1);
  expect_yaw(poses.at("jaw_follower"), M_PI / 2 + 0.5 * (-M_PI + 0.1));
}

TEST(JointStateKinematics, LimitsClampRevoluteAndPrismaticJoints)
{
  auto kinematics = make();
  ASSERT_TRUE(kinematics);
  EXPECT_EQ(kinematics->set_position("shoulder", 3.0), SetResult::Clamped);
  EXPECT_EQ(kinematics->position("shoulder"), 2.0);
  EXPECT_EQ(kinematics->set_position("insertion", -1.0), SetResult::Clamped);
  EXPECT_EQ(kinematics->position("insertion"), 0.05);
  EXPECT_EQ(kinematics->set_position("insertion", 0.3), SetResult::Clamped);
  EXPECT_EQ(kinematics->position("insertion"), 0.2);
  // slider: 0.2 along the arm's x, yawed 2 rad.
  auto poses = kinematics->link_poses();
  expect_position(poses.at("slider"), 0.5 + 0.2 * std::cos(2.0), 0.2 * std::sin(2.0), 0.1);
  kinematics->reset();
  EXPECT_EQ(kinematics->position("shoulder"), 0.0);
  EXPECT_EQ(kinematics->position("insertion"), 0.05);
  EXPECT_FALSE(kinematics->has_positions());
}

TEST(JointStateKinematics, RefusesMimicFixedUnknownJointsAndNonFiniteValues)
{
  auto kinematics = make();
  ASSERT_TRUE(kinematics);
  EXPECT_EQ(kinematics->set_position("grip", 0.2), SetResult::NotActuated);
  EXPECT_EQ(kinematics->set_position("mount", 0.2), SetResult::NotActuated);
  EXPECT_EQ(kinematics->set_position("elbow", 0.2), SetResult::UnknownJoint);
  EXPECT_EQ(kinematics->set_position("shoulder", std::numeric_limits<double>::quiet_NaN()),
    SetResult::NotFinite);
  EXPECT_EQ(kinematics->set_position("spin", std::numeric_limits<double>::infinity()),
    SetResult::NotFinite);
  EXPECT_EQ(kinematics->position("shoulder"), 0.0);
  EXPECT_EQ(kinematics->position("mount"), 0.0);
  EXPECT_TRUE(std::isnan(kinematics->position("elbow")));
  EXPECT_FALSE(kinematics->has_positions());
}

TEST(JointStateKinematics, JointStateOfMismatchedLengthsIsRefusedWhole)
{
  auto kinematics = make();
  ASSERT_TRUE(kinematics);
  auto report = kinematics->apply_joint_state({ "shoulder", "insertion" }, { 1.0 });
  EXPECT_FALSE(report.accepted);
  EXPECT_EQ(report.error,
    "JointState has 2 names but 1 positions (they must match one to one); message ignored");
  EXPECT_EQ(kinematics->position("shoulder"), 0.0);
  // robot_state_publisher refuses a state without positions too (velocity-only messages).
  report = kinematics->apply_joint_state({ "shoulder" }, {});
  EXPECT_FALSE(report.accepted);
  EXPECT_FALSE(kinematics->has_positions());
}

TEST(JointStateKinematics, JointStateIgnoresUnknownNamesAndNaNAndClamps)
{
  auto kinematics = make();
  ASSERT_TRUE(kinematics);
  auto report =
    kinematics->apply_joint_state({ "shoulder", "gripper", "grip", "spin", "insertion" },
      { 0.5, 1.0, 0.3, std::numeric_limits<double>::quiet_NaN(), 9.0 });
  EXPECT_TRUE(report.accepted);
  EXPECT_EQ(report.applied, 2u);
  EXPECT_EQ(report.unknown, (std::vector<std::string>{ "gripper", "grip" }));
  EXPECT_EQ(report.not_finite, (std::vector<std::string>{ "spin" }));
  EXPECT_EQ(report.clamped, (std::vector<std::string>{ "insertion" }));
  EXPECT_EQ(kinematics->position("shoulder"), 0.5);
  EXPECT_EQ(kinematics->position("spin"), 0.0);
  EXPECT_EQ(kinematics->position("insertion"), 0.2);
  EXPECT_NEAR(kinematics->position("grip"), -2 * 0.5 + 0.1, kTolerance);
}

TEST(JointStateKinematics, TransformsFlagFixedJointsStatic)
{
  auto kinematics = make();
  ASSERT_TRUE(kinematics);
  kinematics->set_position("insertion", 0.1);
  const auto transforms = kinematics->joint_transforms();
  ASSERT_EQ(transforms.size(), 6u);
  EXPECT_EQ(transforms[0].child, "column");
  EXPECT_TRUE(transforms[0].is_static);
  for (size_t i = 1; i < transforms.size(); ++i)
    EXPECT_FALSE(transforms[i].is_static) << transforms[i].child;
  for (const auto& transform : transforms)
  {
    if (transform.child == "slider")
      expect_position(transform.transform, 0.1, 0, 0); // parent arm -> slider: the insertion only
  }
}

TEST(JointStateKinematics, BrokenUrdfIsAnError)
{
  std::string error;
  EXPECT_FALSE(JointStateKinematics::from_urdf("<robot", &error));
  EXPECT_FALSE(error.empty());
}
