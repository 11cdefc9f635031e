// ros2vtk — the display manager's bookkeeping in C++ (no rendering, no ROS): nodes added,
// modified and removed keep the renderer's props in step on Update(), link status colours,
// renderer changes, and the registry of displayable managers for a new node kind. Pixels are
// checked by test_display.py (offscreen, with rclpy peers).
#include "vtkROS2DisplayManager.h"
#include "vtkROS2DisplayableManager.h"
#include "vtkROS2ModelNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2SceneNode.h"
#include "vtkROS2Tf2LookupNode.h"
#include "vtkROS2TransformNode.h"

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <gtest/gtest.h>

namespace {

vtkNew<vtkPolyData> Triangle()
{
  vtkNew<vtkPolyData> polyData;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(10, 0, 0);
  points->InsertNextPoint(0, 10, 0);
  polyData->SetPoints(points);
  return polyData;
}

bool SameColor(const double* a, const double* b)
{
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

}

// A node kind of the test's own, and its displayable manager: a text actor with its name.
class TestNoteNode : public vtkROS2SceneNode
{
public:
  static TestNoteNode* New();
  vtkTypeMacro(TestNoteNode, vtkROS2SceneNode);
};
vtkStandardNewMacro(TestNoteNode);

class TestNoteDisplayableManager : public vtkROS2DisplayableManager
{
public:
  static TestNoteDisplayableManager* New();
  vtkTypeMacro(TestNoteDisplayableManager, vtkROS2DisplayableManager);
  bool CanDisplay(vtkROS2SceneNode* node) override
  {
    return TestNoteNode::SafeDownCast(node) != nullptr;
  }

protected:
  vtkProp* CreateProp(vtkROS2SceneNode*) override { return vtkTextActor::New(); }
  void UpdateProp(vtkROS2SceneNode* node, vtkProp* prop) override
  {
    vtkTextActor::SafeDownCast(prop)->SetInput(node->GetName() ? node->GetName() : "");
  }
  void UpdatePose(vtkROS2SceneNode*, vtkProp*) override {}
};
vtkStandardNewMacro(TestNoteDisplayableManager);

TEST(DisplayManager, ModelsAddedModifiedRemovedOnUpdate)
{
  vtkNew<vtkROS2Scene> scene;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkROS2DisplayManager> dm;
  dm->SetScene(scene);
  dm->SetRenderer(renderer);
  EXPECT_FALSE(dm->Update());

  vtkNew<vtkROS2TransformNode> transform;
  scene->AddNode(transform);
  vtkNew<vtkROS2ModelNode> model;
  auto triangle = Triangle();
  model->SetPolyData(triangle);
  model->SetColor(0, 0, 1);
  scene->AddNode(model);
  model->SetParentTransformNodeID(transform->GetID());
  EXPECT_EQ(dm->GetActorForNode(model), nullptr); // observers only note; Update draws
  EXPECT_TRUE(dm->IsUpdatePending());
  EXPECT_TRUE(dm->Update());
  EXPECT_FALSE(dm->Update());
  vtkActor* actor = dm->GetActorForNode(model);
  ASSERT_NE(actor, nullptr);
  EXPECT_TRUE(renderer->HasViewProp(actor));
  EXPECT_EQ(dm->GetNumberOfDisplayedNodes(), 2); // the model and its transform's (hidden) axes
  EXPECT_FALSE(dm->GetPropForNode(transform)->GetVisibility());
  EXPECT_EQ(actor->GetMapper()->GetInput(), triangle.GetPointer());
  EXPECT_EQ(dm->GetNodeForProp(actor), model.GetPointer()); // picking
  vtkNew<vtkActor> stranger;
  EXPECT_EQ(dm->GetNodeForProp(stranger), nullptr);

  vtkNew<vtkMatrix4x4> matrix;
  matrix->SetElement(1, 3, 25.0);
  transform->SetMatrixTransformToParent(matrix);
  EXPECT_TRUE(dm->Update());
  EXPECT_EQ(actor->GetUserMatrix()->GetElement(1, 3), 25.0);

  model->SetColor(1, 0.5, 0);
  model->SetOpacity(0.5);
  model->SetRepresentation(vtkROS2ModelNode::Points);
  EXPECT_TRUE(dm->Update());
  const double orange[3] = { 1, 0.5, 0 };
  EXPECT_TRUE(SameColor(actor->GetProperty()->GetColor(), orange));
  EXPECT_EQ(actor->GetProperty()->GetOpacity(), 0.5);
  EXPECT_EQ(actor->GetProperty()->GetRepresentation(), VTK_POINTS);
  model->SetVisibility(false);
  dm->Update();
  EXPECT_FALSE(actor->GetVisibility());

  dm->SetAxesVisible(true);
  EXPECT_TRUE(dm->Update());
  EXPECT_TRUE(dm->GetPropForNode(transform)->GetVisibility());

  // Removing the transform puts the model in the world; removing the model drops its actor.
  scene->RemoveNode(transform);
  EXPECT_TRUE(dm->Update());
  EXPECT_EQ(actor->GetUserMatrix()->GetElement(1, 3), 0.0);
  scene->RemoveNode(model);
  EXPECT_FALSE(renderer->HasViewProp(actor));
  EXPECT_EQ(dm->GetNumberOfDisplayedNodes(), 0);
}

TEST(DisplayManager, UntrackedLinkInErrorColour)
{
  vtkNew<vtkROS2Scene> scene;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkROS2DisplayManager> dm;
  dm->SetRenderer(renderer);
  vtkNew<vtkROS2Tf2LookupNode> lookup; // no ROS node: it stays "waiting", never tracked
  lookup->SetParentID("base");
  lookup->SetChildID("tool");
  scene->AddNode(lookup);
  vtkNew<vtkROS2TransformNode> placed;
  scene->AddNode(placed);
  vtkNew<vtkROS2ModelNode> model;
  auto triangle = Triangle();
  model->SetPolyData(triangle);
  model->SetColor(0, 1, 0);
  scene->AddNode(model);
  model->SetParentTransformNodeID(lookup->GetID());
  dm->SetScene(scene); // nodes already in the scene are drawn too
  dm->Update();
  vtkActor* actor = dm->GetActorForNode(model);
  ASSERT_NE(actor, nullptr);
  EXPECT_STREQ(lookup->GetLookupStatus(), "waiting");
  EXPECT_TRUE(SameColor(actor->GetProperty()->GetColor(), dm->GetUntrackedColor()));
  model->SetParentTransformNodeID(placed->GetID());
  EXPECT_TRUE(dm->Update());
  const double green[3] = { 0, 1, 0 };
  EXPECT_TRUE(SameColor(actor->GetProperty()->GetColor(), green));
  // A placeholder is a wireframe in the placeholder colour.
  model->SetAttribute("ros2vtk.placeholder", "1");
  dm->Update();
  EXPECT_TRUE(SameColor(actor->GetProperty()->GetColor(), dm->GetPlaceholderColor()));
  EXPECT_EQ(actor->GetProperty()->GetRepresentation(), VTK_WIREFRAME);
}

TEST(DisplayManager, RendererChangeMovesTheProps)
{
  vtkNew<vtkROS2Scene> scene;
  vtkNew<vtkRenderer> first, second;
  vtkNew<vtkROS2DisplayManager> dm;
  dm->SetScene(scene);
  dm->SetRenderer(first);
  vtkNew<vtkROS2ModelNode> model;
  auto triangle = Triangle();
  model->SetPolyData(triangle);
  scene->AddNode(model);
  dm->Update();
  vtkActor* actor = dm->GetActorForNode(model);
  dm->SetRenderer(second);
  EXPECT_FALSE(first->HasViewProp(actor));
  EXPECT_TRUE(second->HasViewProp(actor));
  dm->SetScene(nullptr); // leaving the scene takes every prop away
  EXPECT_FALSE(second->HasViewProp(actor));
  EXPECT_EQ(dm->GetNumberOfDisplayedNodes(), 0);
}

TEST(DisplayManager, ANewNodeKindIsOneClassAndOneRegistration)
{
  vtkNew<vtkROS2Scene> scene;
  vtkNew<TestNoteNode> note;
  note->SetName("hello");
  scene->AddNode(note);
  {
    vtkNew<vtkROS2DisplayManager> before;
    before->SetScene(scene);
    before->Update();
    EXPECT_EQ(before->GetPropForNode(note), nullptr); // no manager knows the kind yet
  }
  vtkROS2DisplayManager::RegisterDisplayableManagerClass(
    []() -> vtkROS2DisplayableManager* { return TestNoteDisplayableManager::New(); });
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkROS2DisplayManager> dm;
  dm->SetScene(scene);
  dm->SetRenderer(renderer);
  dm->Update();
  auto* text = vtkTextActor::SafeDownCast(dm->GetPropForNode(note));
  ASSERT_NE(text, nullptr);
  EXPECT_STREQ(text->GetInput(), "hello");
  EXPECT_TRUE(renderer->HasViewProp(text));
  note->SetName("changed");
  dm->Update();
  EXPECT_STREQ(text->GetInput(), "changed");
}

TEST(DisplayManager, SceneDeletedFirstLeavesNothingBehind)
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkROS2DisplayManager> dm;
  vtkActor* actor = nullptr;
  {
    vtkNew<vtkROS2Scene> scene;
    vtkNew<vtkROS2ModelNode> model;
    auto triangle = Triangle();
    model->SetPolyData(triangle);
    scene->AddNode(model);
    dm->SetScene(scene);
    dm->SetRenderer(renderer);
    dm->Update();
    actor = dm->GetActorForNode(model);
    ASSERT_NE(actor, nullptr);
    EXPECT_EQ(renderer->GetViewProps()->GetNumberOfItems(), 1);
  } // the scene goes first: its nodes are removed with events, the props with them
  EXPECT_EQ(dm->GetScene(), nullptr);
  EXPECT_EQ(dm->GetNumberOfDisplayedNodes(), 0);
  EXPECT_EQ(renderer->GetViewProps()->GetNumberOfItems(), 0);
  EXPECT_TRUE(dm->Update()); // the removal is reported once
  EXPECT_FALSE(dm->Update());
}
