// ros2vtk — model nodes as actors (see the header).
#include "vtkROS2ModelDisplayableManager.h"

#include "vtkROS2DisplayManager.h"
#include "vtkROS2ModelNode.h"
#include "vtkROS2Tf2LookupNode.h"
#include "vtkROS2TransformNode.h"

#include "vtkActor.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

#include <cstring>

vtkStandardNewMacro(vtkROS2ModelDisplayableManager);

//------------------------------------------------------------------------------
bool vtkROS2ModelDisplayableManager::CanDisplay(vtkROS2SceneNode* node)
{
  return vtkROS2ModelNode::SafeDownCast(node) != nullptr;
}

//------------------------------------------------------------------------------
bool vtkROS2ModelDisplayableManager::IsUntracked(vtkROS2SceneNode* node)
{
  auto* model = vtkROS2ModelNode::SafeDownCast(node);
  int depth = 0; // a cycle is the transform node's to report; stop walking it here
  for (vtkROS2TransformNode* transform = model ? model->GetParentTransformNode() : nullptr;
       transform && depth < 1000; transform = transform->GetParentTransformNode(), ++depth)
  {
    auto* lookup = vtkROS2Tf2LookupNode::SafeDownCast(transform);
    // A robot link its robot posed from joint positions (docs/robot-state.md) is not untracked.
    const char* pose = lookup ? lookup->GetAttribute("ros2vtk.linkPose") : nullptr;
    const bool posedByJoints = pose && std::strcmp(pose, "joint positions (no tf)") == 0;
    if (lookup && std::strcmp(lookup->GetLookupStatus(), "ok") != 0 && !posedByJoints)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkROS2ModelDisplayableManager::IsPlaceholder(vtkROS2SceneNode* node)
{
  const char* value = node ? node->GetAttribute("ros2vtk.placeholder") : nullptr;
  return value && std::strcmp(value, "1") == 0;
}

//------------------------------------------------------------------------------
vtkProp* vtkROS2ModelDisplayableManager::CreateProp(vtkROS2SceneNode*)
{
  vtkActor* actor = vtkActor::New();
  vtkNew<vtkPolyDataMapper> mapper;
  actor->SetMapper(mapper);
  actor->SetUserMatrix(vtkNew<vtkMatrix4x4>());
  return actor;
}

//------------------------------------------------------------------------------
void vtkROS2ModelDisplayableManager::UpdateProp(vtkROS2SceneNode* node, vtkProp* prop)
{
  auto* model = vtkROS2ModelNode::SafeDownCast(node);
  auto* actor = vtkActor::SafeDownCast(prop);
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
  if (mapper->GetInput() != model->GetPolyData())
  {
    mapper->SetInputData(model->GetPolyData());
  }
  mapper->SetScalarVisibility(model->GetScalarVisibility() && !IsPlaceholder(node));
  vtkProperty* property = actor->GetProperty();
  property->SetOpacity(model->GetOpacity());
  property->SetPointSize(model->GetPointSize());
  property->SetRepresentation(IsPlaceholder(node) ? VTK_WIREFRAME : model->GetRepresentation());
  property->SetLineWidth(IsPlaceholder(node) ? 2.0 : 1.0);
  actor->SetVisibility(model->GetVisibility() && model->GetPolyData() != nullptr);
}

//------------------------------------------------------------------------------
void vtkROS2ModelDisplayableManager::UpdatePose(vtkROS2SceneNode* node, vtkProp* prop)
{
  auto* model = vtkROS2ModelNode::SafeDownCast(node);
  auto* actor = vtkActor::SafeDownCast(prop);
  vtkMatrix4x4* matrix = actor->GetUserMatrix();
  model->GetMatrixModelToWorld(matrix);
  matrix->Modified();
  // The colour depends on the link status, which changes with the transforms.
  const double* color = model->GetColor();
  const bool untracked = IsUntracked(node);
  if (vtkROS2DisplayManager* manager = this->DisplayManager)
  {
    if (untracked)
    {
      color = manager->GetUntrackedColor();
    }
    else if (IsPlaceholder(node))
    {
      color = manager->GetPlaceholderColor();
    }
  }
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  // An untracked mesh coloured per vertex would hide its status: show the status colour.
  actor->GetMapper()->SetScalarVisibility(
    model->GetScalarVisibility() && !IsPlaceholder(node) && !untracked);
}
