// ros2vtk — point-cloud and shape subscribers as actors (see the header). The actor's polydata is
// its own (points shared with the node's newest message, one vertex cell per point); labels are
// followers beside it in the node's vtkPropAssembly.
#include "vtkROS2PointCloudDisplayableManager.h"

#include "Internal/SubscriberData.hpp"
#include "vtkROS2DisplayManager.h"
#include "vtkROS2SceneNode.h"

#include "ros2vtk/convert/Marker.hpp" // the label arrays' names

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFieldData.h"
#include "vtkFollower.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkVectorText.h"
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

namespace {

/// The label arrays of `polyData` (ros2vtk::convert's Label* field arrays), all or none.
struct Labels
{
  vtkStringArray* text = nullptr;
  vtkDataArray* position = nullptr;
  vtkDataArray* height = nullptr;
  vtkDataArray* color = nullptr;

  explicit Labels(vtkPolyData* polyData)
  {
    vtkFieldData* field = polyData ? polyData->GetFieldData() : nullptr;
    if (!field)
    {
      return;
    }
    auto* names =
      vtkStringArray::SafeDownCast(field->GetAbstractArray(ros2vtk::convert::kLabelTextArray));
    this->position = field->GetArray(ros2vtk::convert::kLabelPositionArray);
    this->height = field->GetArray(ros2vtk::convert::kLabelHeightArray);
    this->color = field->GetArray(ros2vtk::convert::kLabelColorArray);
    const vtkIdType n = names ? names->GetNumberOfValues() : 0;
    if (names && this->position && this->height && this->color &&
      this->position->GetNumberOfComponents() == 3 && this->position->GetNumberOfTuples() == n &&
      this->height->GetNumberOfTuples() == n && this->color->GetNumberOfComponents() == 4 &&
      this->color->GetNumberOfTuples() == n)
    {
      this->text = names;
    }
  }
  vtkIdType size() const { return this->text ? this->text->GetNumberOfValues() : 0; }
};

/// A follower that keeps turning to the camera inside a vtkPropAssembly: the assembly pokes each
/// part's matrix as it was when its paths were built (vtkPropAssembly::RenderOpaqueGeometry),
/// which would freeze a plain vtkFollower in its first orientation.
class LabelFollower : public vtkFollower
{
public:
  static LabelFollower* New();
  vtkTypeMacro(LabelFollower, vtkFollower);
  void PokeMatrix(vtkMatrix4x4* vtkNotUsed(matrix)) override {}
};
vtkStandardNewMacro(LabelFollower);

/// One label: its text as polygons (VTK's vector font), centred on the follower's origin,
/// turned to the camera, capitals `height` high, in its colour, unlit.
vtkSmartPointer<LabelFollower> MakeLabel(
  const std::string& text, double height, const unsigned char rgba[4], vtkCamera* camera)
{
  vtkNew<vtkVectorText> glyphs;
  glyphs->SetText(text.c_str());
  glyphs->Update();
  double b[6];
  glyphs->GetOutput()->GetBounds(b);
  vtkNew<vtkTransform> centre;
  centre->Translate(-0.5 * (b[0] + b[1]), -0.5 * (b[2] + b[3]), 0.0);
  vtkNew<vtkTransformPolyDataFilter> centred;
  centred->SetInputConnection(glyphs->GetOutputPort());
  centred->SetTransform(centre);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(centred->GetOutputPort());
  auto label = vtkSmartPointer<LabelFollower>::New();
  label->SetMapper(mapper);
  label->SetScale(height);
  label->SetCamera(camera);
  label->GetProperty()->SetColor(rgba[0] / 255.0, rgba[1] / 255.0, rgba[2] / 255.0);
  label->GetProperty()->SetOpacity(rgba[3] / 255.0);
  label->GetProperty()->LightingOff();
  return label;
}

}

//------------------------------------------------------------------------------
vtkProp* vtkROS2PointCloudDisplayableManager::CreateProp(vtkROS2SceneNode*)
{
  // Part 0: the points or shapes; then one follower per label (Text markers).
  vtkPropAssembly* assembly = vtkPropAssembly::New();
  vtkNew<vtkActor> actor;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(vtkNew<vtkPolyData>());
  actor->SetMapper(mapper);
  actor->SetUserMatrix(vtkNew<vtkMatrix4x4>());
  actor->GetProperty()->SetRepresentationToPoints();
  assembly->AddPart(actor);
  return assembly;
}

//------------------------------------------------------------------------------
void vtkROS2PointCloudDisplayableManager::UpdateLabels(vtkROS2SceneNode* node, vtkProp* prop)
{
  auto* assembly = vtkPropAssembly::SafeDownCast(prop);
  vtkPropCollection* parts = assembly->GetParts();
  while (parts->GetNumberOfItems() > 1)
  {
    assembly->RemovePart(vtkProp::SafeDownCast(parts->GetItemAsObject(1)));
  }
  const Labels labels(vtkPolyData::SafeDownCast(ros2vtk::display::LastMessageObject(node)));
  vtkCamera* camera = this->GetRenderer() ? this->GetRenderer()->GetActiveCamera() : nullptr;
  for (vtkIdType i = 0; i < labels.size(); ++i)
  {
    unsigned char rgba[4];
    for (int c = 0; c < 4; ++c)
    {
      rgba[c] = static_cast<unsigned char>(labels.color->GetComponent(i, c));
    }
    assembly->AddPart(
      MakeLabel(labels.text->GetValue(i), labels.height->GetTuple1(i), rgba, camera));
  }
}

//------------------------------------------------------------------------------
void vtkROS2PointCloudDisplayableManager::PlaceLabels(
  vtkROS2SceneNode* node, vtkProp* prop, vtkMatrix4x4* toWorld)
{
  vtkPropCollection* parts = vtkPropAssembly::SafeDownCast(prop)->GetParts();
  const Labels labels(vtkPolyData::SafeDownCast(ros2vtk::display::LastMessageObject(node)));
  for (vtkIdType i = 0; i < labels.size() && i + 1 < parts->GetNumberOfItems(); ++i)
  {
    double local[4] = { 0, 0, 0, 1 };
    labels.position->GetTuple(i, local);
    local[3] = 1.0;
    double world[4];
    toWorld->MultiplyPoint(local, world);
    vtkFollower::SafeDownCast(parts->GetItemAsObject(static_cast<int>(i) + 1))
      ->SetPosition(world[0], world[1], world[2]);
  }
}

//------------------------------------------------------------------------------
void vtkROS2PointCloudDisplayableManager::UpdateProp(vtkROS2SceneNode* node, vtkProp* prop)
{
  auto* actor =
    vtkActor::SafeDownCast(vtkPropAssembly::SafeDownCast(prop)->GetParts()->GetItemAsObject(0));
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
  this->UpdateLabels(node, prop);
  this->PlaceLabels(node, prop, actor->GetUserMatrix());
}

//------------------------------------------------------------------------------
void vtkROS2PointCloudDisplayableManager::UpdatePose(vtkROS2SceneNode* node, vtkProp* prop)
{
  auto* actor =
    vtkActor::SafeDownCast(vtkPropAssembly::SafeDownCast(prop)->GetParts()->GetItemAsObject(0));
  vtkMatrix4x4* matrix = actor->GetUserMatrix();
  GetParentTransformToWorld(node, matrix);
  matrix->Modified();
  this->PlaceLabels(node, prop, matrix);
}
