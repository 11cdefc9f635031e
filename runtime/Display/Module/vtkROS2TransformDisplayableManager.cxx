// ros2vtk — transform nodes as labelled axes glyphs (see the header). The prop is a
// vtkPropAssembly of a vtkAxesActor and a vtkBillboardTextActor3D (the label faces the camera).
#include "vtkROS2TransformDisplayableManager.h"

#include "vtkROS2DisplayManager.h"
#include "vtkROS2Tf2LookupNode.h"
#include "vtkROS2TransformNode.h"

#include "vtkAxesActor.h"
#include "vtkBillboardTextActor3D.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"

vtkStandardNewMacro(vtkROS2TransformDisplayableManager);

namespace {

vtkAxesActor* AxesOf(vtkProp* prop)
{
  auto* parts = vtkPropAssembly::SafeDownCast(prop)->GetParts();
  return vtkAxesActor::SafeDownCast(parts->GetItemAsObject(0));
}

vtkBillboardTextActor3D* LabelOf(vtkProp* prop)
{
  auto* parts = vtkPropAssembly::SafeDownCast(prop)->GetParts();
  return vtkBillboardTextActor3D::SafeDownCast(parts->GetItemAsObject(1));
}

}

//------------------------------------------------------------------------------
bool vtkROS2TransformDisplayableManager::CanDisplay(vtkROS2SceneNode* node)
{
  return vtkROS2TransformNode::SafeDownCast(node) != nullptr;
}

//------------------------------------------------------------------------------
const char* vtkROS2TransformDisplayableManager::GetFrameName(vtkROS2SceneNode* node)
{
  auto* lookup = vtkROS2Tf2LookupNode::SafeDownCast(node);
  if (lookup && lookup->GetChildID()[0])
  {
    return lookup->GetChildID();
  }
  const char* name = node ? node->GetName() : nullptr;
  return name ? name : "";
}

//------------------------------------------------------------------------------
vtkProp* vtkROS2TransformDisplayableManager::CreateProp(vtkROS2SceneNode*)
{
  vtkPropAssembly* assembly = vtkPropAssembly::New();
  vtkNew<vtkAxesActor> axes;
  axes->AxisLabelsOff();
  // vtkAxesActor passes a user transform (not a user matrix) on to its shafts and tips.
  axes->SetUserTransform(vtkNew<vtkTransform>());
  vtkNew<vtkBillboardTextActor3D> label;
  label->GetTextProperty()->SetFontSize(14);
  label->GetTextProperty()->SetColor(1.0, 1.0, 0.6);
  label->GetTextProperty()->SetJustificationToLeft();
  label->GetTextProperty()->SetVerticalJustificationToBottom();
  assembly->AddPart(axes);
  assembly->AddPart(label);
  return assembly;
}

//------------------------------------------------------------------------------
void vtkROS2TransformDisplayableManager::UpdateProp(vtkROS2SceneNode* node, vtkProp* prop)
{
  const bool visible = this->DisplayManager && this->DisplayManager->GetAxesVisible();
  const double length = this->DisplayManager ? this->DisplayManager->GetAxesLength() : 50.0;
  vtkAxesActor* axes = AxesOf(prop);
  axes->SetTotalLength(length, length, length);
  axes->SetVisibility(visible);
  vtkBillboardTextActor3D* label = LabelOf(prop);
  label->SetInput(GetFrameName(node));
  label->SetVisibility(visible);
  prop->SetVisibility(visible);
}

//------------------------------------------------------------------------------
void vtkROS2TransformDisplayableManager::UpdatePose(vtkROS2SceneNode* node, vtkProp* prop)
{
  auto* transform = vtkROS2TransformNode::SafeDownCast(node);
  vtkAxesActor* axes = AxesOf(prop);
  vtkNew<vtkMatrix4x4> matrix;
  transform->GetMatrixTransformToWorld(matrix);
  vtkTransform::SafeDownCast(axes->GetUserTransform())->SetMatrix(matrix);
  LabelOf(prop)->SetPosition(
    matrix->GetElement(0, 3), matrix->GetElement(1, 3), matrix->GetElement(2, 3));
}
