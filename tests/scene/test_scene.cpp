// The scene model without DDS: IDs, names, attributes, references, events, save/restore.
#include "vtkROS2NodeNode.h"
#include "vtkROS2PublisherGenericNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SceneNode.h"

#include "vtkCallbackCommand.h"
#include "vtkCollection.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {
// Records (event id, node ID) of every event the scene fires.
struct EventLog
{
  std::vector<std::pair<unsigned long, std::string>> events;
  vtkNew<vtkCallbackCommand> command;

  explicit EventLog(vtkROS2Scene* scene)
  {
    command->SetClientData(this);
    command->SetCallback([](vtkObject*, unsigned long event, void* clientData, void* callData) {
      auto* node = static_cast<vtkROS2SceneNode*>(callData);
      static_cast<EventLog*>(clientData)->events.emplace_back(event, node ? node->GetID() : "");
    });
    this->Scene = scene;
    scene->AddObserver(vtkROS2Scene::NodeAddedEvent, command);
    scene->AddObserver(vtkROS2Scene::NodeRemovedEvent, command);
  }
  ~EventLog() { this->Scene->RemoveObserver(this->command); }
  vtkSmartPointer<vtkROS2Scene> Scene;
};

vtkSmartPointer<vtkROS2NodeNode> AddNodeNode(vtkROS2Scene* scene, const char* name)
{
  auto node = vtkSmartPointer<vtkROS2NodeNode>::New();
  node->SetName(name);
  scene->AddNode(node);
  return node;
}
} // namespace

TEST(Scene, GivesUniqueClassBasedIDsInOrder)
{
  vtkNew<vtkROS2Scene> scene;
  auto a = AddNodeNode(scene, "a");
  auto b = AddNodeNode(scene, "b");
  vtkNew<vtkROS2PublisherGenericNode> pub;
  scene->AddNode(pub);
  EXPECT_STREQ(a->GetID(), "vtkROS2NodeNode1");
  EXPECT_STREQ(b->GetID(), "vtkROS2NodeNode2");
  EXPECT_STREQ(pub->GetID(), "vtkROS2PublisherGenericNode1");
  EXPECT_EQ(scene->GetNumberOfNodes(), 3);
  EXPECT_EQ(scene->GetNthNode(1), b.Get());
  EXPECT_EQ(a->GetScene(), scene.Get());
}

TEST(Scene, DoesNotReuseTheIDOfARemovedNode)
{
  vtkNew<vtkROS2Scene> scene;
  auto a = AddNodeNode(scene, "a");
  ASSERT_TRUE(scene->RemoveNode(a));
  auto b = AddNodeNode(scene, "b");
  EXPECT_STREQ(b->GetID(), "vtkROS2NodeNode2");
  EXPECT_EQ(a->GetScene(), nullptr);
}

TEST(Scene, FindsNodesByIDNameAndClass)
{
  vtkNew<vtkROS2Scene> scene;
  auto a = AddNodeNode(scene, "same");
  auto b = AddNodeNode(scene, "same");
  vtkNew<vtkROS2PublisherGenericNode> pub;
  scene->AddNode(pub);
  EXPECT_EQ(scene->GetNodeByID("vtkROS2NodeNode2"), b.Get());
  EXPECT_EQ(scene->GetNodeByID("nope"), nullptr);
  EXPECT_EQ(scene->GetNodeByID(nullptr), nullptr);
  EXPECT_EQ(scene->GetFirstNodeByName("same"), a.Get());
  EXPECT_EQ(scene->GetFirstNodeByName("other"), nullptr);

  vtkNew<vtkCollection> found;
  scene->GetNodesByClass("vtkROS2NodeNode", found);
  ASSERT_EQ(found->GetNumberOfItems(), 2);
  EXPECT_EQ(found->GetItemAsObject(0), a.Get());
  // Subclasses count (IsA), as in MRML.
  EXPECT_EQ(scene->GetNumberOfNodesByClass("vtkROS2SceneNode"), 3);
  EXPECT_EQ(scene->GetNumberOfNodesByClass("vtkROS2PublisherNode"), 1);
  EXPECT_EQ(scene->GetNthNodeByClass(1, "vtkROS2NodeNode"), b.Get());
  EXPECT_EQ(scene->GetNthNodeByClass(2, "vtkROS2NodeNode"), nullptr);
}

TEST(Scene, FiresAddedAndRemovedEventsWithTheNode)
{
  vtkNew<vtkROS2Scene> scene;
  EventLog log(scene);
  auto a = AddNodeNode(scene, "a");
  scene->RemoveNode(a);
  ASSERT_EQ(log.events.size(), 2u);
  EXPECT_EQ(log.events[0].first, static_cast<unsigned long>(vtkROS2Scene::NodeAddedEvent));
  EXPECT_EQ(log.events[0].second, "vtkROS2NodeNode1");
  EXPECT_EQ(log.events[1].first, static_cast<unsigned long>(vtkROS2Scene::NodeRemovedEvent));
  EXPECT_EQ(log.events[1].second, "vtkROS2NodeNode1");
}

TEST(Scene, RejectsNullAndDoubleMembership)
{
  vtkNew<vtkROS2Scene> scene;
  vtkNew<vtkROS2Scene> other;
  scene->GlobalWarningDisplayOff();
  other->GlobalWarningDisplayOff();
  EXPECT_EQ(scene->AddNode(nullptr), nullptr);
  auto a = AddNodeNode(scene, "a");
  EXPECT_EQ(other->AddNode(a), nullptr);
  EXPECT_EQ(scene->AddNode(a), nullptr);
  EXPECT_FALSE(other->RemoveNode(a));
  EXPECT_EQ(scene->GetNumberOfNodes(), 1);
  scene->GlobalWarningDisplayOn();
}

TEST(SceneNode, NameAndAttributesFireModified)
{
  vtkNew<vtkROS2NodeNode> node;
  int modified = 0;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetClientData(&modified);
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void*) { ++*static_cast<int*>(clientData); });
  node->AddObserver(vtkCommand::ModifiedEvent, counter);

  node->SetName("robot");
  node->SetName("robot"); // unchanged: no event
  node->SetAttribute("color", "red");
  node->SetAttribute("color", "red");
  node->SetAttribute("alpha", "1");
  EXPECT_EQ(modified, 3);
  EXPECT_STREQ(node->GetName(), "robot");
  EXPECT_STREQ(node->GetAttribute("color"), "red");
  EXPECT_EQ(node->GetAttribute("missing"), nullptr);
  EXPECT_STREQ(node->GetAttributeNames(), "alpha color");
  node->RemoveAttribute("color");
  EXPECT_EQ(node->GetAttribute("color"), nullptr);
  EXPECT_EQ(modified, 4);
}

TEST(SceneNode, ReferencesResolveThroughTheSceneAndDieWithTheTarget)
{
  vtkNew<vtkROS2Scene> scene;
  auto a = AddNodeNode(scene, "a");
  auto b = AddNodeNode(scene, "b");
  auto c = AddNodeNode(scene, "c");
  a->SetNodeReferenceID("parent", b->GetID());
  a->AddNodeReferenceID("child", b->GetID());
  a->AddNodeReferenceID("child", c->GetID());
  EXPECT_EQ(a->GetNodeReference("parent"), b.Get());
  EXPECT_EQ(a->GetNumberOfNodeReferences("child"), 2);
  EXPECT_EQ(a->GetNthNodeReference("child", 1), c.Get());
  EXPECT_EQ(a->GetNthNodeReference("child", 2), nullptr);
  EXPECT_STREQ(a->GetNodeReferenceRoles(), "child parent");

  scene->RemoveNode(b);
  EXPECT_EQ(a->GetNodeReferenceID("parent"), nullptr);
  EXPECT_EQ(a->GetNumberOfNodeReferences("child"), 1);
  EXPECT_STREQ(a->GetNthNodeReferenceID("child", 0), c->GetID());

  a->SetNodeReferenceID("child", nullptr);
  EXPECT_EQ(a->GetNumberOfNodeReferences("child"), 0);
}

// The scene indexes who refers to whom (vtkROS2Scene::NoteReferrer), so a removal visits only the
// referrers: every way a reference can come into being must reach that index.
TEST(SceneNode, EveryWayOfReferringIsForgottenWhenTheTargetGoes)
{
  vtkNew<vtkROS2Scene> scene;
  auto target = AddNodeNode(scene, "target");
  const std::string targetID = target->GetID();

  vtkNew<vtkROS2NodeNode> joinedLater; // referred before it was in any scene
  joinedLater->SetNodeReferenceID("parent", targetID.c_str());
  ASSERT_TRUE(scene->AddNode(joinedLater));

  auto rejoined = AddNodeNode(scene, "rejoined"); // left the scene and came back
  rejoined->SetNodeReferenceID("parent", targetID.c_str());
  ASSERT_TRUE(scene->RemoveNode(rejoined));
  ASSERT_TRUE(scene->AddNode(rejoined));

  auto gone = AddNodeNode(scene, "gone"); // removed first: keeps its reference, out of the scene
  gone->SetNodeReferenceID("parent", targetID.c_str());
  ASSERT_TRUE(scene->RemoveNode(gone));

  ASSERT_TRUE(scene->RemoveNode(target));
  EXPECT_EQ(joinedLater->GetNodeReferenceID("parent"), nullptr);
  EXPECT_EQ(rejoined->GetNodeReferenceID("parent"), nullptr);
  EXPECT_STREQ(gone->GetNodeReferenceID("parent"), targetID.c_str());
}

TEST(SceneNode, ReferencesReadFromAFileAreForgottenWhenTheTargetGoes)
{
  vtkNew<vtkROS2Scene> saved;
  auto first = AddNodeNode(saved, "first"); // written before the node it refers to
  auto later = AddNodeNode(saved, "later");
  first->AddNodeReferenceID("watch", later->GetID());
  later->AddNodeReferenceID("watch", first->GetID());

  vtkNew<vtkROS2Scene> restored;
  ASSERT_TRUE(restored->ReadFromXMLString(saved->WriteToXMLString().c_str()));
  vtkROS2SceneNode* firstBack = restored->GetFirstNodeByName("first");
  vtkROS2SceneNode* laterBack = restored->GetFirstNodeByName("later");
  ASSERT_NE(firstBack, nullptr);
  ASSERT_NE(laterBack, nullptr);
  ASSERT_EQ(firstBack->GetNodeReference("watch"), laterBack);
  ASSERT_TRUE(restored->RemoveNode(laterBack));
  EXPECT_EQ(firstBack->GetNodeReferenceID("watch"), nullptr);
  restored->Clear();
  EXPECT_EQ(restored->GetNumberOfNodes(), 0);
}

TEST(SceneNode, AReferenceOutsideASceneDoesNotResolve)
{
  vtkNew<vtkROS2NodeNode> loose;
  loose->SetNodeReferenceID("parent", "vtkROS2NodeNode1");
  EXPECT_STREQ(loose->GetNodeReferenceID("parent"), "vtkROS2NodeNode1");
  EXPECT_EQ(loose->GetNodeReference("parent"), nullptr);
}

TEST(SceneFile, RoundTripsIDsNamesAttributesAndReferences)
{
  vtkNew<vtkROS2Scene> scene;
  auto a = AddNodeNode(scene, "first node");
  auto b = AddNodeNode(scene, "second <&> node");
  a->SetAttribute("note", "quote \" and ampersand &");
  a->SetNodeReferenceID("peer", b->GetID());
  const std::string xml = scene->WriteToXMLString();

  vtkNew<vtkROS2Scene> restored;
  ASSERT_TRUE(restored->ReadFromXMLString(xml.c_str())) << xml;
  ASSERT_EQ(restored->GetNumberOfNodes(), 2);
  vtkROS2SceneNode* ra = restored->GetNodeByID("vtkROS2NodeNode1");
  ASSERT_NE(ra, nullptr);
  EXPECT_STREQ(ra->GetClassName(), "vtkROS2NodeNode");
  EXPECT_STREQ(ra->GetName(), "first node");
  EXPECT_STREQ(ra->GetAttribute("note"), "quote \" and ampersand &");
  EXPECT_EQ(ra->GetNodeReference("peer"), restored->GetNodeByID("vtkROS2NodeNode2"));
  EXPECT_STREQ(restored->GetNodeByID("vtkROS2NodeNode2")->GetName(), "second <&> node");

  // New nodes after a restore do not collide with restored IDs.
  auto c = AddNodeNode(restored, "c");
  EXPECT_STREQ(c->GetID(), "vtkROS2NodeNode3");
}

TEST(SceneFile, WritesAndReadsAFile)
{
  vtkNew<vtkROS2Scene> scene;
  AddNodeNode(scene, "on disk");
  const std::string path = ::testing::TempDir() + "ros2vtk_scene_test.xml";
  ASSERT_TRUE(scene->WriteToXMLFile(path.c_str()));
  vtkNew<vtkROS2Scene> restored;
  ASSERT_TRUE(restored->ReadFromXMLFile(path.c_str()));
  ASSERT_EQ(restored->GetNumberOfNodes(), 1);
  EXPECT_STREQ(restored->GetNthNode(0)->GetName(), "on disk");
  std::remove(path.c_str());
}

TEST(SceneFile, RejectsBadDocumentsWithoutCrashing)
{
  vtkNew<vtkROS2Scene> scene;
  scene->GlobalWarningDisplayOff();
  EXPECT_FALSE(scene->ReadFromXMLString(nullptr));
  EXPECT_FALSE(scene->ReadFromXMLString("not xml at all <"));
  EXPECT_FALSE(scene->ReadFromXMLString("<Other version=\"1\"/>"));
  EXPECT_FALSE(scene->ReadFromXMLString("<ROS2Scene version=\"99\"/>"));
  EXPECT_FALSE(
    scene->ReadFromXMLString("<ROS2Scene version=\"1\"><vtkNoSuchNode id=\"x1\"/></ROS2Scene>"));
  EXPECT_FALSE(scene->ReadFromXMLString(
    "<ROS2Scene version=\"1\"><vtkROS2NodeNode name=\"no id\"/></ROS2Scene>"));
  EXPECT_FALSE(scene->ReadFromXMLString("<ROS2Scene version=\"1\"><vtkROS2NodeNode id=\"a\"/>"
                                        "<vtkROS2NodeNode id=\"a\"/></ROS2Scene>"));
  EXPECT_FALSE(
    scene->ReadFromXMLString("<ROS2Scene version=\"1\"><vtkROS2NodeNode id=\"a\">"
                             "<Attribute value=\"no name\"/></vtkROS2NodeNode></ROS2Scene>"));
  EXPECT_FALSE(scene->ReadFromXMLFile("/nonexistent/dir/scene.xml"));
  EXPECT_FALSE(scene->WriteToXMLFile("/nonexistent/dir/scene.xml"));
  scene->GlobalWarningDisplayOn();
}

// Issue 11.6: a failing read left the scene cleared (or half-read). Reading is atomic now: after
// each failing read the scene is exactly as before, and no node was removed or added.
TEST(SceneFile, FailingReadsLeaveTheSceneUnchanged)
{
  vtkNew<vtkROS2Scene> scene;
  auto a = AddNodeNode(scene, "kept a");
  auto b = AddNodeNode(scene, "kept b");
  a->SetAttribute("note", "still here");
  a->SetNodeReferenceID("peer", b->GetID());
  const std::string before = scene->WriteToXMLString();
  const std::string valid = "<vtkROS2NodeNode id=\"n1\" name=\"new\"/>";
  std::string deep = "<ROS2Scene version=\"1\">";
  for (int i = 0; i < 150000; ++i)
    deep += "<x>";
  const std::vector<std::string> failing = {
    "<ROS2Scene version=\"1\">" + valid + "<vtkNoSuchNode id=\"x1\"/></ROS2Scene>",
    "<ROS2Scene version=\"1\">" + valid + "<vtkROS2NodeNode name=\"no id\"/></ROS2Scene>",
    "<ROS2Scene version=\"1\">" + valid + "<vtkROS2NodeNode id=\"n1\"/></ROS2Scene>",
    "<ROS2Scene version=\"1\">" + valid +
      "<vtkROS2NodeNode id=\"n2\"><Attribute value=\"no name\"/></vtkROS2NodeNode></ROS2Scene>",
    "<ROS2Scene version=\"1\">" + valid, // truncated file
    "<ROS2Scene version=\"2\">" + valid + "</ROS2Scene>",
    deep,
  };
  EventLog log(scene);
  scene->GlobalWarningDisplayOff();
  for (size_t i = 0; i < failing.size(); ++i)
  {
    EXPECT_FALSE(scene->ReadFromXMLString(failing[i].c_str())) << i;
    EXPECT_EQ(scene->WriteToXMLString(), before) << "after failing read " << i;
  }
  scene->GlobalWarningDisplayOn();
  EXPECT_TRUE(log.events.empty()) << log.events.size() << " nodes were added or removed";
  EXPECT_EQ(scene->GetNodeByID(a->GetID()), a.GetPointer());
  EXPECT_EQ(a->GetNodeReference("peer"), b.GetPointer());
  // A valid read still replaces everything.
  ASSERT_TRUE(
    scene->ReadFromXMLString(("<ROS2Scene version=\"1\">" + valid + "</ROS2Scene>").c_str()));
  ASSERT_EQ(scene->GetNumberOfNodes(), 1);
  EXPECT_STREQ(scene->GetNthNode(0)->GetName(), "new");
}
