// ros2vtk — point-cloud and shape subscribers as actors (see the header). The actor's polydata is
// its own (points shared with the node's newest message, one vertex cell per point).
#include "vtkROS2PointCloudDisplayableManager.h"

#include "SubscriberData.hpp"
#include "vtkROS2DisplayManager.h"
#include "vtkROS2SceneNode.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

#include <sstream>

vtkStandardNewMacro(vtkROS2PointCloudDisplayableManager);

//------------------------------------------------------------------------------
bool vtkROS2PointCloudDisplayableManager::CanDisplay(vtkROS2SceneNode* node)
{
  return ros2vtk::display::IsSubscriberOf(node, "vtkPoints") ||
    ros2vtk::display::IsSubscriberOf(node, "vtkPolyData");
}

//------------------------------------------------------------------------------
vtkProp* vtkROS2PointCloudDisplayableManager::CreateProp(vtkROS2SceneNode*)
{
  vtkActor* actor = vtkActor::New();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(vtkNew<vtkPolyData>());
  actor->SetMapper(mapper);
  actor->SetUserMatrix(vtkNew<vtkMatrix4x4>());
  actor->GetProperty()->SetRepresentationToPoints();
  return actor;
}

//------------------------------------------------------------------------------
void vtkROS2PointCloudDisplayableManager::UpdateProp(vtkROS2SceneNode* node, vtkProp* prop)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
  vtkPolyData* cloud = mapper->GetInput();
  vtkObject* message = ros2vtk::display::LastMessageObject(node);
  auto* polyData = vtkPolyData::SafeDownCast(message);
  // Shapes (lines, polygons, strips: e.g. a MarkerArray drawn by its kind) are drawn as they
  // are, surfaces lit, with their RGBA colours; a cloud gets one vertex per point.
  const bool shapes = polyData &&
    (polyData->GetNumberOfLines() + polyData->GetNumberOfPolys() + polyData->GetNumberOfStrips()) >
      0;
  if (shapes)
  {
    cloud->ShallowCopy(polyData);
  }
  else if (polyData)
  {
    cloud->Initialize();
    cloud->SetPoints(polyData->GetPoints());
    cloud->GetPointData()->ShallowCopy(polyData->GetPointData());
  }
  else if (auto* points = vtkPoints::SafeDownCast(message))
  {
    cloud->Initialize();
    cloud->SetPoints(points);
  }
  const vtkIdType count = cloud->GetPoints() ? cloud->GetNumberOfPoints() : 0;
  if (!shapes)
  {
    vtkNew<vtkCellArray> vertices;
    for (vtkIdType i = 0; i < count; ++i)
    {
      vertices->InsertNextCell(1, &i);
    }
    cloud->SetVerts(vertices);
  }
  cloud->Modified();
  if (shapes)
  {
    actor->GetProperty()->SetRepresentationToSurface();
  }
  else
  {
    actor->GetProperty()->SetRepresentationToPoints();
  }
  vtkDataArray* scalars = cloud->GetPointData()->GetScalars();
  mapper->SetScalarVisibility(scalars != nullptr);
  // Unsigned char RGB(A) scalars (marker colours) are colours; anything else goes through the
  // lookup table over its range.
  const bool colours = scalars && scalars->GetDataType() == VTK_UNSIGNED_CHAR &&
    (scalars->GetNumberOfComponents() == 3 || scalars->GetNumberOfComponents() == 4);
  if (colours)
  {
    mapper->SetColorModeToDirectScalars();
  }
  else
  {
    mapper->SetColorModeToDefault();
  }
  if (scalars && !colours)
  {
    mapper->SetScalarRange(scalars->GetRange());
  }
  double color[3] = { 0.5, 1.0, 0.5 };
  if (const char* text = node->GetAttribute("ros2vtk.display.color"))
  {
    std::istringstream values(text);
    double rgb[3];
    if (values >> rgb[0] >> rgb[1] >> rgb[2])
    {
      color[0] = rgb[0];
      color[1] = rgb[1];
      color[2] = rgb[2];
    }
  }
  actor->GetProperty()->SetColor(color);
  actor->GetProperty()->SetPointSize(
    this->DisplayManager ? this->DisplayManager->GetPointSize() : 3.0);
  actor->SetVisibility(count > 0);
}

//------------------------------------------------------------------------------
void vtkROS2PointCloudDisplayableManager::UpdatePose(vtkROS2SceneNode* node, vtkProp* prop)
{
  vtkMatrix4x4* matrix = vtkActor::SafeDownCast(prop)->GetUserMatrix();
  GetParentTransformToWorld(node, matrix);
  matrix->Modified();
}
