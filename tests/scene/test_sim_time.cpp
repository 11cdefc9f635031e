// Simulated time on a ROS node (use_sim_time, /clock), with a second ROS node of this process as
// the simulator: the parameter is declared off, switches through the node's API and through the
// parameter store (the path the services take), the clock is 0 until the first /clock, then
// follows it; tf broadcasts carry that time; a jump back clears the tf buffer; the setting is
// saved in scene files. rclpy's side of the same is tests/interop/test_sim_time.py.
#include "ros2vtk_test/SceneTestSupport.hpp"
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2Tf2BroadcasterNode.h"
#include "vtkROS2Tf2LookupNode.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>

namespace {
using ros2vtk_test::SpinUntil;

constexpr vtkTypeInt64 kSecond = 1000000000;

vtkTypeInt64 WallNanoseconds()
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::system_clock::now().time_since_epoch())
    .count();
}

class SimTimeTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    vtkOutputWindow::SetInstance(this->Output);
    this->Node = this->Logic->GetDefaultROS2Node();
    ASSERT_NE(this->Node, nullptr);
  }
  void TearDown() override { vtkOutputWindow::SetInstance(nullptr); }

  /// A second ROS node publishing rosgraph_msgs/Clock on /clock (a generic node: the type has
  /// no mapping rule), matched with this->Node's /clock subscription.
  void StartSimulator()
  {
    this->Simulator = vtkSmartPointer<vtkROS2NodeNode>::New();
    this->Logic->GetScene()->AddNode(this->Simulator);
    ASSERT_TRUE(this->Simulator->Create("simulator"));
    this->ClockPublisher = vtkROS2PublisherGenericNode::SafeDownCast(
      this->Simulator->CreateAndAddPublisherNode("rosgraph_msgs/msg/Clock", "/clock"));
    ASSERT_NE(this->ClockPublisher, nullptr) << this->Output->Errors;
  }

  /// Publishes `sec`.`nanosec` until this->Node's clock reads it (best effort: one may be lost).
  bool DriveClockTo(int sec, unsigned nanosec)
  {
    const std::string yaml =
      "{clock: {sec: " + std::to_string(sec) + ", nanosec: " + std::to_string(nanosec) + "}}";
    const vtkTypeInt64 expected = sec * kSecond + nanosec;
    return SpinUntil(this->Logic, [&] {
      this->ClockPublisher->PublishYAML(yaml.c_str());
      return this->Node->GetNodeTimeNanoseconds() == expected;
    });
  }

  vtkNew<ros2vtk_test::CapturingOutputWindow> Output;
  vtkNew<vtkROS2Logic> Logic;
  vtkROS2NodeNode* Node = nullptr;
  vtkSmartPointer<vtkROS2NodeNode> Simulator;
  vtkROS2PublisherGenericNode* ClockPublisher = nullptr;
};
} // namespace

TEST_F(SimTimeTest, UseSimTimeIsDeclaredOffAndTheClockIsTheSystemClock)
{
  EXPECT_EQ(this->Node->PrintOwnParameter("use_sim_time"), "use_sim_time (bool): false");
  EXPECT_FALSE(this->Node->GetUseSimTime());
  const vtkTypeInt64 before = WallNanoseconds();
  const vtkTypeInt64 now = this->Node->GetNodeTimeNanoseconds();
  EXPECT_LE(before, now);
  EXPECT_LE(now, WallNanoseconds());
  // Another type is refused, as rclpy refuses a non-bool use_sim_time.
  EXPECT_FALSE(this->Node->SetParameterAsInteger("use_sim_time", 1));
  EXPECT_FALSE(this->Node->GetUseSimTime());
}

TEST_F(SimTimeTest, ZeroUntilTheFirstClockThenFollowsItAndBroadcastsCarryIt)
{
  ASSERT_TRUE(this->Node->SetUseSimTime(true));
  EXPECT_TRUE(this->Node->GetUseSimTime());
  EXPECT_EQ(this->Node->PrintOwnParameter("use_sim_time"), "use_sim_time (bool): true");
  EXPECT_EQ(this->Node->GetNodeTimeNanoseconds(), 0);
  EXPECT_FALSE(this->Node->GetSimTimeReceived());

  this->StartSimulator();
  ASSERT_TRUE(this->DriveClockTo(1000, 500))
    << "node time stayed " << this->Node->GetNodeTimeNanoseconds();
  EXPECT_TRUE(this->Node->GetSimTimeReceived());
  EXPECT_DOUBLE_EQ(this->Node->GetNodeTime(), 1000.0000005);
  ASSERT_TRUE(this->DriveClockTo(1001, 0));

  // A broadcast stamped in simulated time, looked up by the simulator's own (wall-clock) node
  // and by this node: both see the simulated stamp.
  vtkROS2Tf2BroadcasterNode* broadcaster =
    this->Node->CreateAndAddTf2BroadcasterNode("world", "tool");
  vtkROS2Tf2LookupNode* remote = this->Simulator->CreateAndAddTf2LookupNode("world", "tool");
  vtkROS2Tf2LookupNode* local = this->Node->CreateAndAddTf2LookupNode("world", "tool");
  ASSERT_NE(broadcaster, nullptr);
  ASSERT_NE(remote, nullptr);
  ASSERT_NE(local, nullptr);
  vtkNew<vtkMatrix4x4> matrix;
  matrix->SetElement(0, 3, 25.0);
  ASSERT_TRUE(SpinUntil(this->Logic,
    [&] {
      broadcaster->Broadcast(matrix.GetPointer());
      return std::string(remote->GetLookupStatus()) == "ok" &&
        std::string(local->GetLookupStatus()) == "ok";
    }))
    << remote->GetLookupStatus() << " / " << local->GetLookupStatus();
  EXPECT_DOUBLE_EQ(remote->GetLastLookupTime(), 1001.0);
  EXPECT_DOUBLE_EQ(local->GetLastLookupTime(), 1001.0);
  // Ages compare in each node's clock: 0 s of simulated time here; the wall-clock node sees a
  // transform from 1970 (why a node needs the simulator's time to judge its transforms).
  EXPECT_DOUBLE_EQ(local->GetLastLookupAge(), 0.0);
  ASSERT_TRUE(this->DriveClockTo(1003, 500000000));
  EXPECT_DOUBLE_EQ(local->GetLastLookupAge(), 2.5);
  EXPECT_GT(remote->GetLastLookupAge(), 1.0e9);
}

TEST_F(SimTimeTest, ASetThroughTheParameterStoreSwitchesBothWays)
{
  // SetParameterAsBool takes the path of a SetParameters request: the store, then the time source.
  ASSERT_TRUE(this->Node->SetParameterAsBool("use_sim_time", true));
  EXPECT_TRUE(this->Node->GetUseSimTime());
  EXPECT_EQ(this->Node->GetNodeTimeNanoseconds(), 0);
  this->StartSimulator();
  ASSERT_TRUE(this->DriveClockTo(1000, 0));
  ASSERT_TRUE(this->Node->SetParameterAsBool("use_sim_time", false));
  EXPECT_FALSE(this->Node->GetUseSimTime());
  EXPECT_GT(this->Node->GetNodeTimeNanoseconds(), WallNanoseconds() - 60 * kSecond);
  // /clock is no longer heard: the node's time stays on the system clock.
  for (int i = 0; i < 20; ++i)
  {
    this->ClockPublisher->PublishYAML("{clock: {sec: 5, nanosec: 0}}");
    this->Logic->Spin();
  }
  EXPECT_GT(this->Node->GetNodeTimeNanoseconds(), WallNanoseconds() - 60 * kSecond);
}

TEST_F(SimTimeTest, AJumpBackInTimeClearsTheTfBuffer)
{
  ASSERT_TRUE(this->Node->SetUseSimTime(true));
  this->StartSimulator();
  ASSERT_TRUE(this->DriveClockTo(1000, 0));
  vtkROS2Tf2BroadcasterNode* broadcaster =
    this->Node->CreateAndAddTf2BroadcasterNode("map", "robot");
  vtkROS2Tf2LookupNode* lookup = this->Node->CreateAndAddTf2LookupNode("map", "robot");
  ASSERT_NE(broadcaster, nullptr);
  ASSERT_NE(lookup, nullptr);
  vtkNew<vtkMatrix4x4> matrix;
  ASSERT_TRUE(SpinUntil(this->Logic, [&] {
    broadcaster->Broadcast(matrix.GetPointer());
    return std::string(lookup->GetLookupStatus()) == "ok";
  }));
  EXPECT_DOUBLE_EQ(lookup->GetLastLookupTime(), 1000.0);
  EXPECT_EQ(this->Output->Warnings.find("jumped back in time"), std::string::npos)
    << this->Output->Warnings;
  SpinUntil(
    this->Logic, [] { return false; }, 0.3); // no broadcast in flight any more
  // The replay restarts at 10 s: the transform stamped 1000 s must not stay the "latest" one,
  // so the buffer forgets it and the lookup fails until a new broadcast comes.
  ASSERT_TRUE(this->DriveClockTo(10, 0));
  this->Logic->Spin();
  EXPECT_STREQ(lookup->GetLookupStatus(), "failed");
  EXPECT_NE(this->Output->Warnings.find("jumped back in time"), std::string::npos)
    << this->Output->Warnings;
  ASSERT_TRUE(SpinUntil(this->Logic, [&] {
    broadcaster->Broadcast(matrix.GetPointer());
    return std::string(lookup->GetLookupStatus()) == "ok";
  }));
  EXPECT_DOUBLE_EQ(lookup->GetLastLookupTime(), 10.0);
}

TEST_F(SimTimeTest, SetBeforeCreateAppliesAtCreateAndIsSavedInSceneFiles)
{
  vtkNew<vtkROS2NodeNode> node;
  EXPECT_FALSE(node->GetUseSimTime());
  ASSERT_TRUE(node->SetUseSimTime(true));
  EXPECT_TRUE(node->GetUseSimTime());
  vtkNew<vtkXMLDataElement> element;
  node->WriteXML(element);
  int saved = 0;
  ASSERT_TRUE(element->GetScalarAttribute("useSimTime", saved));
  EXPECT_EQ(saved, 1);

  vtkNew<vtkROS2NodeNode> restored;
  ASSERT_TRUE(restored->ReadXML(element));
  EXPECT_TRUE(restored->GetUseSimTime());
  this->Logic->GetScene()->AddNode(restored);
  ASSERT_TRUE(restored->Create("restored_sim"));
  EXPECT_EQ(restored->PrintOwnParameter("use_sim_time"), "use_sim_time (bool): true");
  EXPECT_TRUE(restored->GetUseSimTime());
  // Never a wall-clock time: 0 until a simulator speaks.
  EXPECT_EQ(restored->GetNodeTimeNanoseconds(), 0);
}

TEST_F(SimTimeTest, TfFramesAsYAMLListsEveryFrameWithItsDelayToTheNodeClock)
{
  vtkNew<vtkROS2NodeNode> notCreated;
  EXPECT_EQ(notCreated->GetTf2FramesAsYAML(), "");
  ASSERT_TRUE(this->Node->SetUseSimTime(true));
  this->StartSimulator();
  ASSERT_TRUE(this->DriveClockTo(1000, 0));
  EXPECT_EQ(this->Node->GetTf2FramesAsYAML(), "[]");
  vtkROS2Tf2BroadcasterNode* moving = this->Node->CreateAndAddTf2BroadcasterNode("map", "robot");
  vtkROS2Tf2BroadcasterNode* fixed = this->Node->CreateAndAddTf2BroadcasterNode("map", "camera");
  ASSERT_NE(moving, nullptr);
  ASSERT_NE(fixed, nullptr);
  fixed->SetStatic(true);
  vtkNew<vtkMatrix4x4> matrix;
  std::string yaml;
  ASSERT_TRUE(SpinUntil(this->Logic,
    [&] {
      moving->Broadcast(matrix.GetPointer());
      fixed->Broadcast(matrix.GetPointer());
      yaml = this->Node->GetTf2FramesAsYAML();
      return yaml.find("robot:") != std::string::npos && yaml.find("camera:") != std::string::npos;
    }))
    << yaml;
  // The moving frame was stamped 1000 s by the node's clock; the clock moves on 2.5 s.
  ASSERT_TRUE(this->DriveClockTo(1002, 500000000));
  yaml = this->Node->GetTf2FramesAsYAML();
  const std::size_t robot = yaml.find("robot:\n");
  const std::size_t camera = yaml.find("camera:\n");
  ASSERT_NE(robot, std::string::npos) << yaml;
  ASSERT_NE(camera, std::string::npos) << yaml;
  const std::string robotEntry = yaml.substr(robot, yaml.find("buffer_length", robot) - robot);
  const std::string cameraEntry = yaml.substr(camera, yaml.find("buffer_length", camera) - camera);
  EXPECT_NE(robotEntry.find("parent: 'map'"), std::string::npos) << yaml;
  EXPECT_NE(robotEntry.find("most_recent_transform: 1000.000000"), std::string::npos) << yaml;
  EXPECT_NE(robotEntry.find("transform_delay: 2.500"), std::string::npos) << yaml;
  // A static frame has no stamp: 0.
  EXPECT_NE(cameraEntry.find("parent: 'map'"), std::string::npos) << yaml;
  EXPECT_NE(cameraEntry.find("most_recent_transform: 0.000000"), std::string::npos) << yaml;
}
