// Every mapping rule's classes are registered, and the names users type resolve to them: short
// names, aliases, class names, the paper's vtkMRMLROS2<...>Node spellings and ROS type names.
#include "NodeClassRegistry.hpp"
#include "vtkROS2PublisherImageNode.h"
#include "vtkROS2PublisherStringNode.h"
#include "vtkROS2SubscriberImageNode.h"
#include "vtkROS2SubscriberPoseStampedNode.h"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <string>

#include "ros2vtkNodesRegister.hpp" // ros2vtk_register_ros2vtkNodes_nodes()

namespace {
using ros2vtk::scene::NodeClassRegistry;
using ros2vtk::scene::NodeDirection;

class NodesRegistryTest : public ::testing::Test
{
protected:
  void SetUp() override { ros2vtk_register_ros2vtkNodes_nodes(); }
  NodeClassRegistry& Registry = NodeClassRegistry::instance();

  // The class a type string creates (through the factory, so aliases are checked too).
  std::string CreatedClass(NodeDirection direction, const std::string& type)
  {
    const auto resolution = this->Registry.resolve(direction, type);
    if (!resolution.mapped_class)
    {
      return "unresolved: " + resolution.error;
    }
    vtkSmartPointer<vtkROS2SceneNode> node;
    node.TakeReference(resolution.mapped_class->create());
    return node->GetClassName();
  }
};
} // namespace

TEST_F(NodesRegistryTest, EveryRuleHasBothClassesWithItsRosType)
{
  // The 17 rules of msg_specs/mappings/*.toml, by hand.
  const std::pair<const char*, const char*> rules[] = {
    { "String", "std_msgs/msg/String" },
    { "Bool", "std_msgs/msg/Bool" },
    { "Int", "std_msgs/msg/Int64" },
    { "Double", "std_msgs/msg/Float64" },
    { "Empty", "std_msgs/msg/Empty" },
    { "IntArray", "std_msgs/msg/Int64MultiArray" },
    { "DoubleArray", "std_msgs/msg/Float64MultiArray" },
    { "IntTable", "std_msgs/msg/Int64MultiArray" },
    { "DoubleTable", "std_msgs/msg/Float64MultiArray" },
    { "PoseStamped", "geometry_msgs/msg/PoseStamped" },
    { "TransformStamped", "geometry_msgs/msg/TransformStamped" },
    { "PoseArray", "geometry_msgs/msg/PoseArray" },
    { "WrenchStamped", "geometry_msgs/msg/WrenchStamped" },
    { "Image", "sensor_msgs/msg/Image" },
    { "PointCloud", "sensor_msgs/msg/PointCloud" },
    { "PointCloud2", "sensor_msgs/msg/PointCloud2" },
    { "JointState", "sensor_msgs/msg/JointState" },
  };
  for (const auto& rule : rules)
  {
    for (auto direction : { NodeDirection::Publisher, NodeDirection::Subscriber })
    {
      const auto* info = this->Registry.find_short_name(direction, rule.first);
      ASSERT_NE(info, nullptr) << rule.first;
      EXPECT_EQ(info->class_name,
        std::string("vtkROS2") + ros2vtk::scene::to_string(direction) + rule.first + "Node");
      EXPECT_EQ(info->ros_type, rule.second);
      EXPECT_EQ(this->CreatedClass(direction, rule.first), info->class_name);
    }
  }
}

TEST_F(NodesRegistryTest, ShortClassAndMrmlNamesResolve)
{
  EXPECT_EQ(this->CreatedClass(NodeDirection::Publisher, "String"), "vtkROS2PublisherStringNode");
  EXPECT_EQ(this->CreatedClass(NodeDirection::Publisher, "vtkROS2PublisherStringNode"),
    "vtkROS2PublisherStringNode");
  EXPECT_EQ(this->CreatedClass(NodeDirection::Publisher, "vtkMRMLROS2PublisherStringNode"),
    "vtkROS2PublisherStringNode");
  EXPECT_EQ(this->CreatedClass(NodeDirection::Subscriber, "vtkMRMLROS2SubscriberPoseStampedNode"),
    "vtkROS2SubscriberPoseStampedNode");
}

TEST_F(NodesRegistryTest, AliasCreatesThePrimaryClass)
{
  EXPECT_EQ(
    this->CreatedClass(NodeDirection::Publisher, "UInt8Image"), "vtkROS2PublisherImageNode");
  EXPECT_EQ(this->CreatedClass(NodeDirection::Subscriber, "vtkMRMLROS2SubscriberUInt8ImageNode"),
    "vtkROS2SubscriberImageNode");
  EXPECT_EQ(this->CreatedClass(NodeDirection::Publisher, "vtkROS2PublisherUInt8ImageNode"),
    "vtkROS2PublisherImageNode");
}

TEST_F(NodesRegistryTest, RosTypeResolvesToItsOnlyMappedClassOrTheGenericNode)
{
  // Image has an alias, but the alias carries no ROS type: still exactly one class.
  EXPECT_EQ(this->CreatedClass(NodeDirection::Subscriber, "sensor_msgs/msg/Image"),
    "vtkROS2SubscriberImageNode");
  EXPECT_EQ(this->CreatedClass(NodeDirection::Publisher, "geometry_msgs/PoseStamped"),
    "vtkROS2PublisherPoseStampedNode");
  // Int64MultiArray has two rules (IntArray, IntTable): a ROS type alone is ambiguous.
  const auto resolution =
    this->Registry.resolve(NodeDirection::Publisher, "std_msgs/msg/Int64MultiArray");
  EXPECT_EQ(resolution.mapped_class, nullptr);
  ASSERT_NE(resolution.generic_type, nullptr);
  EXPECT_STREQ(resolution.generic_type->ros_type, "std_msgs/msg/Int64MultiArray");
}

TEST_F(NodesRegistryTest, WrongDirectionAndUnknownNamesAreErrors)
{
  auto resolution =
    this->Registry.resolve(NodeDirection::Publisher, "vtkMRMLROS2SubscriberStringNode");
  EXPECT_EQ(resolution.mapped_class, nullptr);
  EXPECT_NE(resolution.error.find("CreateAndAddSubscriberNode"), std::string::npos)
    << resolution.error;
  resolution = this->Registry.resolve(NodeDirection::Subscriber, "Strin");
  EXPECT_EQ(resolution.mapped_class, nullptr);
  EXPECT_NE(resolution.error.find("PoseStamped"), std::string::npos)
    << "the message lists the known short names: " << resolution.error;
}

TEST_F(NodesRegistryTest, RegisteringTwiceIsHarmless)
{
  const size_t before = this->Registry.classes(NodeDirection::Publisher).size();
  ros2vtk_register_ros2vtkNodes_nodes();
  EXPECT_EQ(this->Registry.classes(NodeDirection::Publisher).size(), before);
  // 17 rules + the UInt8Image alias, plus whatever the runtime registers of its own.
  EXPECT_GE(before, 18u);
}
