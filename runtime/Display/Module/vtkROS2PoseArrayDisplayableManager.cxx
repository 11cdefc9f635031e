// ros2vtk — pose-array subscribers as arrows (see the header): a vtkGlyph3D of an arrow source
// over the poses' positions, oriented by each pose's x axis.
#include "vtkROS2PoseArrayDisplayableManager.h"

#include "Internal/SubscriberData.hpp"
#include "vtkROS2DisplayManager.h"
#include "vtkROS2SceneNode.h"

#include "vtkActor.h"
#include "vtkArrowSource.h"
#include "vtkDoubleArray.h"
#include "vtkGlyph3D.h"
#include "vtkLinearTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkTransformCollection.h"

vtkStandardNewMacro(vtkROS2PoseArrayDisplayableManager);

//------------------------------------------------------------------------------
bool vtkROS2PoseArrayDisplayableManager::CanDisplay(vtkROS2SceneNode* node)
{
  return ros2vtk::display::IsSubscriberOf(node, "vtkTransformCollection");
}

//------------------------------------------------------------------------------
vtkProp* vtkROS2PoseArrayDisplayableManager::CreateProp(vtkROS2SceneNode*)
{
  vtkNew<vtkGlyph3D> glyphs;
  vtkNew<vtkArrowSource> arrow;
  glyphs->SetSourceConnection(arrow->GetOutputPort());
  glyphs->SetInputData(vtkNew<vtkPolyData>());
  glyphs->SetVectorModeToUseVector();
  glyphs->SetScaleModeToDataScalingOff();
  glyphs->OrientOn();
  vtkActor* actor = vtkActor::New();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(glyphs->GetOutputPort());
  mapper->ScalarVisibilityOff();
  actor->SetMapper(mapper);
  actor->SetUserMatrix(vtkNew<vtkMatrix4x4>());
  actor->GetProperty()->SetColor(1.0, 0.3, 0.1);
  return actor;
}

//------------------------------------------------------------------------------
void vtkROS2PoseArrayDisplayableManager::UpdateProp(vtkROS2SceneNode* node, vtkProp* prop)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  auto* glyphs = vtkGlyph3D::SafeDownCast(actor->GetMapper()->GetInputAlgorithm());
  auto* poses = vtkPolyData::SafeDownCast(glyphs->GetInputDataObject(0, 0));
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> directions;
  directions->SetNumberOfComponents(3);
  directions->SetName("direction");
  if (auto* collection =
        vtkTransformCollection::SafeDownCast(ros2vtk::display::LastMessageObject(node)))
  {
    collection->InitTraversal();
    while (vtkLinearTransform* pose = collection->GetNextItem())
    {
      vtkMatrix4x4* matrix = pose->GetMatrix();
      points->InsertNextPoint(
        matrix->GetElement(0, 3), matrix->GetElement(1, 3), matrix->GetElement(2, 3));
      directions->InsertNextTuple3(
        matrix->GetElement(0, 0), matrix->GetElement(1, 0), matrix->GetElement(2, 0));
    }
  }
  poses->Initialize();
  poses->SetPoints(points);
  poses->GetPointData()->SetVectors(directions);
  poses->Modified();
  glyphs->SetScaleFactor(this->DisplayManager ? this->DisplayManager->GetArrowLength() : 50.0);
  actor->SetVisibility(points->GetNumberOfPoints() > 0);
}

//------------------------------------------------------------------------------
void vtkROS2PoseArrayDisplayableManager::UpdatePose(vtkROS2SceneNode* node, vtkProp* prop)
{
  vtkMatrix4x4* matrix = vtkActor::SafeDownCast(prop)->GetUserMatrix();
  GetParentTransformToWorld(node, matrix);
  matrix->Modified();
}
