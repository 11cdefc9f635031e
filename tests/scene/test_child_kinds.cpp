// Issue 10 item 1 and issue 11 item 3: the ROS node's children are one generic kind of thing.
// - A scene node class written here, outside the runtime (one class plus one registration
//   line), takes part in spin (OnROS2NodeSpin), save and load like the runtime's own kinds.
// - Finding a child by its key goes through an index: creating N tf2 lookups visits O(N)
//   children, not O(N^2) (counted, never timed); loading a whole robot of N links likewise.
#include "NodeClassRegistry.hpp"
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2RobotNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2Tf2LookupNode.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "../robot/chain_urdf.hpp"

namespace {
const char* const CounterRole = "testCounter";
} // namespace

/// A child kind unknown to the runtime: counts the spins of its ROS node, saves a label.
class vtkTestSpinCounterNode : public vtkROS2SceneNode
{
public:
  static vtkTestSpinCounterNode* New();
  vtkTypeMacro(vtkTestSpinCounterNode, vtkROS2SceneNode);

  int Spins = 0;
  std::string Label;

  int OnROS2NodeSpin(vtkROS2NodeNode*) override
  {
    ++this->Spins;
    return 0;
  }
  std::string GetROS2NodeChildKey() const override { return this->Label; }
  void WriteXML(vtkXMLDataElement* element) override
  {
    this->Superclass::WriteXML(element);
    element->SetAttribute("label", this->Label.c_str());
  }
  bool ReadXML(vtkXMLDataElement* element) override
  {
    if (!this->Superclass::ReadXML(element))
    {
      return false;
    }
    const char* label = element->GetAttribute("label");
    this->Label = label ? label : "";
    return true;
  }

protected:
  vtkTestSpinCounterNode() = default;
};
vtkStandardNewMacro(vtkTestSpinCounterNode);

namespace {
// The one registration line (lets a scene file create the class by name).
const bool Registered = ros2vtk::scene::NodeClassRegistry::instance().add(
  { "", "vtkTestSpinCounterNode", "", ros2vtk::scene::NodeDirection::Other,
    [] {
      return static_cast<vtkROS2SceneNode*>(vtkTestSpinCounterNode::New());
    } },
  nullptr);
} // namespace

TEST(ChildKinds, ANodeClassFromOutsideTheRuntimeSpinsSavesAndLoads)
{
  ASSERT_TRUE(Registered);
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* rosNode = logic->GetDefaultROS2Node();
  ASSERT_NE(rosNode, nullptr);
  vtkNew<vtkTestSpinCounterNode> counter;
  counter->Label = "first";
  logic->GetScene()->AddNode(counter);
  rosNode->AddChild(CounterRole, counter);
  EXPECT_EQ(counter->GetROS2Node(), rosNode);
  EXPECT_EQ(rosNode->FindChild(CounterRole, "first"), counter.GetPointer());

  rosNode->Spin();
  rosNode->Spin();
  EXPECT_EQ(counter->Spins, 2);

  const std::string xml = logic->GetScene()->WriteToXMLString();
  EXPECT_NE(xml.find("<vtkTestSpinCounterNode"), std::string::npos) << xml;

  vtkNew<vtkROS2Logic> other;
  ASSERT_TRUE(other->GetScene()->ReadFromXMLString(xml.c_str()));
  auto* restored =
    vtkTestSpinCounterNode::SafeDownCast(other->GetScene()->GetNodeByID(counter->GetID()));
  ASSERT_NE(restored, nullptr);
  EXPECT_EQ(restored->Label, "first");
  vtkROS2NodeNode* restoredNode = other->GetDefaultROS2Node();
  ASSERT_EQ(restored->GetROS2Node(), restoredNode);
  EXPECT_EQ(restoredNode->FindChild(CounterRole, "first"), restored);
  restoredNode->Spin();
  EXPECT_EQ(restored->Spins, 1);

  // Removed from the scene: no longer a child, no longer spun.
  ASSERT_TRUE(restoredNode->RemoveChild(CounterRole, restored));
  EXPECT_EQ(restoredNode->FindChild(CounterRole, "first"), nullptr);
}

namespace {
// Child visits while creating `count` lookups (each: a find that misses, then an add).
vtkTypeUInt64 VisitsToCreateLookups(int count)
{
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* rosNode = logic->GetDefaultROS2Node();
  const vtkTypeUInt64 before = rosNode->GetNumberOfChildVisits();
  for (int i = 0; i < count; ++i)
  {
    const std::string child = "link" + std::to_string(i);
    EXPECT_EQ(rosNode->GetTf2LookupNodeByParentChild("world", child.c_str()), nullptr);
    EXPECT_NE(rosNode->CreateAndAddTf2LookupNode("world", child.c_str()), nullptr);
  }
  const vtkTypeUInt64 visits = rosNode->GetNumberOfChildVisits() - before;
  // Every one is still found (and a changed key is found under its new value).
  EXPECT_NE(rosNode->GetTf2LookupNodeByParentChild("world", "link0"), nullptr);
  vtkROS2Tf2LookupNode* last =
    rosNode->GetTf2LookupNodeByParentChild("world", ("link" + std::to_string(count - 1)).c_str());
  EXPECT_NE(last, nullptr);
  last->SetChildID("renamed");
  EXPECT_EQ(rosNode->GetTf2LookupNodeByParentChild("world", "renamed"), last);
  logic->GetScene()->Clear();
  return visits;
}
} // namespace

TEST(ChildKinds, CreatingLookupsVisitsChildrenLinearly)
{
  const vtkTypeUInt64 small = VisitsToCreateLookups(500);
  const vtkTypeUInt64 large = VisitsToCreateLookups(2000);
  // A scan per creation would visit ~N^2/2 children (125 000 and 2 000 000); the index visits
  // a few per creation.
  EXPECT_LE(small, 4u * 500u);
  EXPECT_LE(large, 4u * 2000u);
  EXPECT_LE(large, 5u * small); // 4x the lookups, not 16x the visits
}

namespace {
// Child visits while loading a URDF chain of `links` links from a file: the robot node makes one
// lookup (and one model) per link, each found through the index first.
vtkTypeUInt64 VisitsToLoadChainRobot(int links)
{
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
    ("ros2vtk_chain_" + std::to_string(links) + "_" + std::to_string(::getpid()) + ".urdf");
  std::ofstream(file) << ros2vtk_test::chain_urdf(links);
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* rosNode = logic->GetDefaultROS2Node();
  const vtkTypeUInt64 before = rosNode->GetNumberOfChildVisits();
  vtkROS2RobotNode* robot = rosNode->CreateAndAddRobotNodeFromFile("chain", file.string().c_str());
  logic->Spin(); // the robot builds its links on the spin that takes the description
  const vtkTypeUInt64 visits = rosNode->GetNumberOfChildVisits() - before;
  EXPECT_NE(robot, nullptr);
  if (robot)
  {
    EXPECT_TRUE(robot->IsLoaded()) << robot->GetLastError();
    EXPECT_EQ(robot->GetNumberOfLinks(), links);
  }
  logic->GetScene()->Clear();
  std::filesystem::remove(file);
  return visits;
}
} // namespace

TEST(ChildKinds, LoadingARobotVisitsChildrenLinearly)
{
  const vtkTypeUInt64 small = VisitsToLoadChainRobot(500);
  const vtkTypeUInt64 large = VisitsToLoadChainRobot(4000);
  // Lookups found by a scan would visit ~N^2/2 children (125 000 and 8 000 000).
  EXPECT_LE(small, 8u * 500u);
  EXPECT_LE(large, 8u * 4000u);
  EXPECT_LE(large, 10u * small); // 8x the links, not 64x the visits
}
