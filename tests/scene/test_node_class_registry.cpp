// Node classes by the three name forms, ROS type names, generic fallback, unknown types.
#include "ros2vtk_test/SceneTestSupport.hpp"
#include "NodeClassRegistry.hpp"
#include "TestStringNodes.h"
#include "vtkROS2Logic.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SubscriberGenericNode.h"

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

using ros2vtk::scene::NodeClassRegistry;
using ros2vtk::scene::NodeDirection;

namespace {
using ros2vtk_test::CapturingOutputWindow;

class NodeClassRegistryTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    RegisterTestStringNodes();
    vtkOutputWindow::SetInstance(this->Output);
  }
  void TearDown() override { vtkOutputWindow::SetInstance(nullptr); }
  vtkNew<CapturingOutputWindow> Output;
};
} // namespace

TEST_F(NodeClassRegistryTest, ResolvesShortClassAndMRMLNames)
{
  const auto& registry = NodeClassRegistry::instance();
  for (const char* name :
    { "TestString", "vtkROS2PublisherTestStringNode", "vtkMRMLROS2PublisherTestStringNode" })
  {
    const auto resolution = registry.resolve(NodeDirection::Publisher, name);
    ASSERT_NE(resolution.mapped_class, nullptr) << name << ": " << resolution.error;
    EXPECT_EQ(resolution.mapped_class->class_name, "vtkROS2PublisherTestStringNode") << name;
  }
  const auto subscriber =
    registry.resolve(NodeDirection::Subscriber, "vtkMRMLROS2SubscriberTestStringNode");
  ASSERT_NE(subscriber.mapped_class, nullptr) << subscriber.error;
  EXPECT_EQ(subscriber.mapped_class->class_name, "vtkROS2SubscriberTestStringNode");
}

TEST_F(NodeClassRegistryTest, SlicerClassNamesFindOurEquivalents)
{
  auto& registry = NodeClassRegistry::instance();
  const std::pair<const char*, const char*> expected[] = {
    { "vtkMRMLModelNode", "vtkROS2ModelNode" },
    { "vtkMRMLLinearTransformNode", "vtkROS2TransformNode" },
    { "vtkMRMLTransformNode", "vtkROS2TransformNode" },
    { "vtkMRMLROS2RobotNode", "vtkROS2RobotNode" },
    { "vtkROS2RobotNode", "vtkROS2RobotNode" },
  };
  for (const auto& pair : expected)
  {
    const auto* info = registry.find_class(pair.first);
    ASSERT_NE(info, nullptr) << pair.first;
    EXPECT_EQ(info->class_name, pair.second) << pair.first;
  }
  EXPECT_EQ(registry.find_class("vtkMRMLScalarVolumeNode"), nullptr);

  std::string error;
  EXPECT_FALSE(registry.add_alias("vtkROS2ModelNode", "vtkROS2TransformNode", &error));
  EXPECT_NE(error.find("is a registered class"), std::string::npos) << error;
  EXPECT_FALSE(registry.add_alias("vtkMRMLModelNode", "vtkROS2TransformNode", &error));
  EXPECT_NE(error.find("already names 'vtkROS2ModelNode'"), std::string::npos) << error;
  EXPECT_FALSE(registry.add_alias("vtkMRMLSomethingNode", "vtkROS2NoSuchNode", &error));
  EXPECT_NE(error.find("unknown class 'vtkROS2NoSuchNode'"), std::string::npos) << error;
  EXPECT_TRUE(registry.add_alias("vtkMRMLModelNode", "vtkROS2ModelNode", &error)) << error;

  // And through the scene: what a Slicer script calls.
  vtkNew<vtkROS2Scene> scene;
  auto* model = scene->AddNewNodeByClass("vtkMRMLModelNode", "needle");
  ASSERT_NE(model, nullptr);
  EXPECT_TRUE(model->IsA("vtkROS2ModelNode"));
  EXPECT_STREQ(model->GetName(), "needle");
}

TEST_F(NodeClassRegistryTest, AClassOfTheOtherDirectionNamesTheRightCall)
{
  const auto resolution = NodeClassRegistry::instance().resolve(
    NodeDirection::Publisher, "vtkROS2SubscriberTestStringNode");
  EXPECT_EQ(resolution.mapped_class, nullptr);
  EXPECT_NE(resolution.error.find("CreateAndAddSubscriberNode"), std::string::npos)
    << resolution.error;
}

TEST_F(NodeClassRegistryTest, ARosTypeWithOneMappedClassGivesThatClass)
{
  for (const char* name : { "std_msgs/msg/String", "std_msgs/String" })
  {
    const auto resolution = NodeClassRegistry::instance().resolve(NodeDirection::Subscriber, name);
    ASSERT_NE(resolution.mapped_class, nullptr) << name << ": " << resolution.error;
    EXPECT_EQ(resolution.mapped_class->class_name, "vtkROS2SubscriberTestStringNode");
  }
}

TEST_F(NodeClassRegistryTest, ARosTypeWithoutMappedClassGivesTheGenericNode)
{
  for (const char* name : { "geometry_msgs/msg/Point", "geometry_msgs/Point" })
  {
    const auto resolution = NodeClassRegistry::instance().resolve(NodeDirection::Publisher, name);
    EXPECT_EQ(resolution.mapped_class, nullptr);
    ASSERT_NE(resolution.generic_type, nullptr) << name << ": " << resolution.error;
    EXPECT_STREQ(resolution.generic_type->ros_type, "geometry_msgs/msg/Point");
  }
}

TEST_F(NodeClassRegistryTest, UnknownTypesListTheKnownNames)
{
  for (const char* name : { "NoSuchType", "vtkROS2PublisherNoSuchNode", "no_pkg/msg/Nothing", "" })
  {
    const auto resolution = NodeClassRegistry::instance().resolve(NodeDirection::Publisher, name);
    EXPECT_EQ(resolution.mapped_class, nullptr) << name;
    EXPECT_EQ(resolution.generic_type, nullptr) << name;
    EXPECT_NE(resolution.error.find(std::string("'") + name + "'"), std::string::npos)
      << resolution.error;
    EXPECT_NE(resolution.error.find("TestString"), std::string::npos) << resolution.error;
    EXPECT_NE(resolution.error.find("geometry_msgs/msg/Point"), std::string::npos)
      << resolution.error;
  }
}

TEST_F(NodeClassRegistryTest, RefusesIncompleteAndConflictingClasses)
{
  auto& registry = NodeClassRegistry::instance();
  std::string error;
  EXPECT_FALSE(registry.add({ "X", "", "", NodeDirection::Publisher, nullptr }, &error));
  EXPECT_FALSE(error.empty());
  error.clear();
  // Same short name as the registered TestString publisher, different class.
  EXPECT_FALSE(registry.add(
    { "TestString", "vtkROS2PublisherOtherNode", "std_msgs/msg/String", NodeDirection::Publisher,
      [] {
        return static_cast<vtkROS2SceneNode*>(nullptr);
      } },
    &error));
  EXPECT_NE(error.find("TestString"), std::string::npos) << error;
  // Registering the same class again is harmless.
  RegisterTestStringNodes();
}

TEST_F(NodeClassRegistryTest, ListsRegisteredClassesSpaceSeparated)
{
  vtkNew<vtkROS2NodeNode> node;
  const std::string publishers = node->GetRegisteredROS2PublisherNodes();
  EXPECT_NE(publishers.find("vtkROS2PublisherTestStringNode"), std::string::npos) << publishers;
  EXPECT_EQ(publishers.find("Subscriber"), std::string::npos) << publishers;
  const std::string subscribers = node->GetRegisteredROS2SubscriberNodes();
  EXPECT_NE(subscribers.find("vtkROS2SubscriberTestStringNode"), std::string::npos) << subscribers;
}

TEST_F(NodeClassRegistryTest, CreateAndAddAcceptsEveryNameForm)
{
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  ASSERT_NE(node, nullptr) << this->Output->Errors;
  auto* a = node->CreateAndAddPublisherNode("TestString", "/a");
  auto* b = node->CreateAndAddPublisherNode("vtkROS2PublisherTestStringNode", "/b");
  auto* c = node->CreateAndAddPublisherNode("vtkMRMLROS2PublisherTestStringNode", "/c");
  auto* d = node->CreateAndAddPublisherNode("geometry_msgs/Point", "/d");
  auto* e = node->CreateAndAddSubscriberNode("geometry_msgs/msg/Point", "/e");
  ASSERT_TRUE(a && b && c && d && e) << this->Output->Errors;
  EXPECT_STREQ(a->GetClassName(), "vtkROS2PublisherTestStringNode");
  EXPECT_STREQ(c->GetClassName(), "vtkROS2PublisherTestStringNode");
  EXPECT_STREQ(d->GetClassName(), "vtkROS2PublisherGenericNode");
  EXPECT_STREQ(d->GetROSType(), "geometry_msgs/msg/Point");
  EXPECT_STREQ(e->GetClassName(), "vtkROS2SubscriberGenericNode");
  EXPECT_STREQ(b->GetTopic(), "/b");
  EXPECT_TRUE(b->IsAddedToROS2Node());
  EXPECT_EQ(node->GetPublisherNodeByTopic("/c"), c);
  EXPECT_EQ(node->GetSubscriberNodeByTopic("/e"), e);
  EXPECT_EQ(node->GetNumberOfPublisherNodes(), 4);
  EXPECT_EQ(logic->GetScene()->GetNumberOfNodes(), 6);
}

TEST_F(NodeClassRegistryTest, CreateAndAddWithAnUnknownTypeFailsListingKnownNames)
{
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  ASSERT_NE(node, nullptr);
  EXPECT_EQ(node->CreateAndAddPublisherNode("Strnig", "/typo"), nullptr);
  EXPECT_NE(this->Output->Errors.find("Strnig"), std::string::npos) << this->Output->Errors;
  EXPECT_NE(this->Output->Errors.find("TestString"), std::string::npos) << this->Output->Errors;
  EXPECT_EQ(logic->GetScene()->GetNumberOfNodes(), 1); // nothing half-made left behind
}

TEST_F(NodeClassRegistryTest, CreateAndAddRefusesASecondEndpointOnATopicAndBadTopics)
{
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  ASSERT_NE(node, nullptr);
  ASSERT_NE(node->CreateAndAddPublisherNode("TestString", "/once"), nullptr);
  EXPECT_EQ(node->CreateAndAddPublisherNode("TestString", "/once"), nullptr);
  EXPECT_EQ(node->CreateAndAddPublisherNode("TestString", "bad topic name!"), nullptr);
  EXPECT_EQ(node->CreateAndAddPublisherNode(nullptr, "/x"), nullptr);
  EXPECT_EQ(node->GetNumberOfPublisherNodes(), 1);
  EXPECT_EQ(logic->GetScene()->GetNumberOfNodes(), 2);
}

TEST_F(NodeClassRegistryTest, RemoveAndDeleteTakesTheNodeOutOfDDSAndScene)
{
  vtkNew<vtkROS2Logic> logic;
  vtkROS2NodeNode* node = logic->GetDefaultROS2Node();
  ASSERT_NE(node, nullptr);
  vtkSmartPointer<vtkROS2PublisherNode> pub =
    node->CreateAndAddPublisherNode("TestString", "/gone");
  ASSERT_NE(pub, nullptr);
  EXPECT_TRUE(node->RemoveAndDeletePublisherNode("/gone"));
  EXPECT_FALSE(pub->IsAddedToROS2Node());
  EXPECT_EQ(pub->GetScene(), nullptr);
  EXPECT_EQ(node->GetPublisherNodeByTopic("/gone"), nullptr);
  EXPECT_FALSE(node->RemoveAndDeletePublisherNode("/gone"));
  EXPECT_FALSE(node->RemoveAndDeleteSubscriberNode("/never"));
}

TEST_F(NodeClassRegistryTest, ANodeThatIsNotCreatedOrNotInASceneRefusesEndpoints)
{
  vtkNew<vtkROS2NodeNode> loose;
  EXPECT_EQ(loose->CreateAndAddPublisherNode("TestString", "/x"), nullptr);
  vtkNew<vtkROS2Scene> scene;
  vtkNew<vtkROS2NodeNode> notCreated;
  scene->AddNode(notCreated);
  EXPECT_EQ(notCreated->CreateAndAddSubscriberNode("TestString", "/x"), nullptr);
  EXPECT_NE(this->Output->Errors.find("Create"), std::string::npos) << this->Output->Errors;
  EXPECT_EQ(notCreated->Spin(), 0);
  EXPECT_EQ(notCreated->GetWakeUpFileDescriptor(), -1);
}
