// ros2vtk — slice views with model intersections (see the header). The slice is a
// vtkImageResliceMapper cut by the view's plane; each model has a transform -> cutter -> actor
// pipeline whose transform is only touched when the model moved, so an Update with nothing new
// re-runs no filter.
#include "vtkROS2SliceView.h"

#include "Internal/SubscriberData.hpp"
#include "vtkROS2ModelNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2TransformNode.h"
#include "vtkROS2VolumeNode.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCollection.h"
#include "vtkCutter.h"
#include "vtkImageData.h"
#include "vtkImageProperty.h"
#include "vtkImageResliceMapper.h"
#include "vtkImageSlice.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>

vtkStandardNewMacro(vtkROS2SliceView);

namespace {

struct Orientation
{
  const char* name;
  double normal[3];
  double viewUp[3];
  double cameraSide; // +1: the camera is on the +normal side of the plane, -1: the other
};

// Slicer's slice orientations (vtkMRMLSliceNode::SetOrientationTo...), world = RAS: axial has
// patient right (+x) on the screen's left and anterior up (seen from the feet); sagittal has
// anterior on the left, superior up; coronal has patient right on the left, superior up.
const Orientation kOrientations[] = {
  { "axial", { 0, 0, 1 }, { 0, 1, 0 }, -1.0 },
  { "sagittal", { 1, 0, 0 }, { 0, 0, 1 }, -1.0 },
  { "coronal", { 0, 1, 0 }, { 0, 0, 1 }, 1.0 },
};

// Intersection lines sit this far (mm) in front of the slice so they are drawn over it.
constexpr double kLineOffset = 0.5;

struct ModelCut
{
  vtkWeakPointer<vtkROS2ModelNode> Model;
  vtkNew<vtkTransform> ToWorld;
  vtkNew<vtkTransformPolyDataFilter> Transformer;
  vtkNew<vtkCutter> Cutter;
  vtkNew<vtkActor> Actor;
  bool Seen = false;
};

}

class vtkROS2SliceView::vtkInternals
{
public:
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkWeakPointer<vtkROS2Scene> Scene;
  int Orientation = 0;
  vtkSmartPointer<vtkImageData> Image;
  vtkWeakPointer<vtkROS2SceneNode> VolumeNode;
  vtkNew<vtkImageData> NodeImage; // shallow copy of the volume node's newest image
  vtkMTimeType VolumeNodeTime = 0;
  double Center[3] = { 0, 0, 0 };
  double Window = 0, Level = 0;
  double FieldOfView = 0;
  vtkNew<vtkPlane> Plane;
  vtkNew<vtkImageResliceMapper> SliceMapper;
  vtkNew<vtkImageSlice> Slice;
  std::map<vtkROS2ModelNode*, std::unique_ptr<ModelCut>> Cuts;
  bool ViewChanged = true; // plane, camera or slice properties need applying
  int Intersected = 0;

  vtkImageData* CurrentImage()
  {
    return this->VolumeNode ? this->NodeImage.GetPointer() : this->Image.GetPointer();
  }
};

//------------------------------------------------------------------------------
vtkROS2SliceView::vtkROS2SliceView()
  : Internals(new vtkInternals)
{
  vtkInternals& internals = *this->Internals;
  internals.SliceMapper->SetSlicePlane(internals.Plane);
  internals.SliceMapper->SliceFacesCameraOff();
  internals.SliceMapper->SliceAtFocalPointOff();
  internals.Slice->SetMapper(internals.SliceMapper);
  internals.Slice->VisibilityOff();
}

//------------------------------------------------------------------------------
vtkROS2SliceView::~vtkROS2SliceView()
{
  this->SetRenderer(nullptr);
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::SetRenderer(vtkRenderer* renderer)
{
  vtkInternals& internals = *this->Internals;
  if (internals.Renderer == renderer)
  {
    return;
  }
  if (vtkRenderer* old = internals.Renderer)
  {
    old->RemoveViewProp(internals.Slice);
    for (auto& cut : internals.Cuts)
    {
      old->RemoveViewProp(cut.second->Actor);
    }
  }
  internals.Renderer = renderer;
  if (renderer)
  {
    renderer->AddViewProp(internals.Slice);
    for (auto& cut : internals.Cuts)
    {
      renderer->AddViewProp(cut.second->Actor);
    }
  }
  internals.ViewChanged = true;
  this->Modified();
}

vtkRenderer* vtkROS2SliceView::GetRenderer() const
{
  return this->Internals->Renderer;
}
vtkROS2Scene* vtkROS2SliceView::GetScene() const
{
  return this->Internals->Scene;
}
vtkImageData* vtkROS2SliceView::GetImageData() const
{
  return this->Internals->Image;
}
vtkROS2SceneNode* vtkROS2SliceView::GetVolumeNode() const
{
  return this->Internals->VolumeNode;
}
vtkImageSlice* vtkROS2SliceView::GetImageSlice() const
{
  return this->Internals->Slice;
}
int vtkROS2SliceView::GetNumberOfIntersectedModels() const
{
  return this->Internals->Intersected;
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::SetScene(vtkROS2Scene* scene)
{
  this->Internals->Scene = scene;
  this->Internals->ViewChanged = true;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkROS2SliceView::SetOrientation(const char* orientation)
{
  for (int i = 0; i < 3; ++i)
  {
    if (orientation && std::strcmp(orientation, kOrientations[i].name) == 0)
    {
      this->Internals->Orientation = i;
      this->Internals->ViewChanged = true;
      this->Modified();
      return true;
    }
  }
  vtkErrorMacro("SetOrientation: '" << (orientation ? orientation : "(null)")
                                    << "' is not one of axial, sagittal, coronal");
  return false;
}

//------------------------------------------------------------------------------
const char* vtkROS2SliceView::GetOrientation() const
{
  return kOrientations[this->Internals->Orientation].name;
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::SetImageData(vtkImageData* image)
{
  this->Internals->Image = image;
  this->Internals->ViewChanged = true;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::SetVolumeNode(vtkROS2SceneNode* node)
{
  if (node && !ros2vtk::display::IsSubscriberOf(node, "vtkImageData") &&
    !vtkROS2VolumeNode::SafeDownCast(node))
  {
    vtkErrorMacro("SetVolumeNode: " << node->GetClassName()
                                    << " is neither a volume node nor receives vtkImageData");
    return;
  }
  this->Internals->VolumeNode = node;
  this->Internals->VolumeNodeTime = 0;
  this->Internals->ViewChanged = true;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::SetSliceCenter(double x, double y, double z)
{
  double* center = this->Internals->Center;
  if (center[0] != x || center[1] != y || center[2] != z)
  {
    center[0] = x;
    center[1] = y;
    center[2] = z;
    this->Internals->ViewChanged = true;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::GetSliceCenter(double center[3]) const
{
  std::copy(this->Internals->Center, this->Internals->Center + 3, center);
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::SetWindowLevel(double window, double level)
{
  this->Internals->Window = window;
  this->Internals->Level = level;
  this->Internals->ViewChanged = true;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::SetFieldOfView(double halfHeight)
{
  this->Internals->FieldOfView = halfHeight;
  this->Internals->ViewChanged = true;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkROS2SliceView::Update()
{
  vtkInternals& internals = *this->Internals;
  bool changed = false;
  // A volume node brings its image on the spins that received one.
  if (vtkROS2SceneNode* node = internals.VolumeNode)
  {
    if (node->GetMTime() != internals.VolumeNodeTime)
    {
      internals.VolumeNodeTime = node->GetMTime();
      auto* volumeNode = vtkROS2VolumeNode::SafeDownCast(node);
      if (auto* image = volumeNode
          ? volumeNode->GetImageData()
          : vtkImageData::SafeDownCast(ros2vtk::display::LastMessageObject(node)))
      {
        internals.NodeImage->ShallowCopy(image);
        internals.NodeImage->Modified();
        internals.ViewChanged = true;
      }
    }
  }
  // A volume node under a transform is resliced where it sits (vtkImageResliceMapper takes the
  // prop's matrix into account); an image or a subscriber is taken in world coordinates.
  {
    vtkNew<vtkMatrix4x4> imageToWorld;
    if (auto* volumeNode = vtkROS2VolumeNode::SafeDownCast(internals.VolumeNode))
    {
      if (vtkROS2TransformNode* parent = volumeNode->GetParentTransformNode())
      {
        parent->GetMatrixTransformToWorld(imageToWorld);
      }
    }
    vtkMatrix4x4* current = internals.Slice->GetUserMatrix();
    bool differs = current == nullptr;
    for (int k = 0; k < 16 && !differs; ++k)
    {
      differs = current->GetElement(k / 4, k % 4) != imageToWorld->GetElement(k / 4, k % 4);
    }
    if (differs)
    {
      vtkNew<vtkMatrix4x4> copy;
      copy->DeepCopy(imageToWorld);
      internals.Slice->SetUserMatrix(copy);
      internals.ViewChanged = true;
    }
  }
  if (internals.ViewChanged)
  {
    const Orientation& orientation = kOrientations[internals.Orientation];
    internals.Plane->SetOrigin(internals.Center);
    internals.Plane->SetNormal(const_cast<double*>(orientation.normal));
    vtkImageData* image = internals.CurrentImage();
    internals.Slice->SetVisibility(image != nullptr);
    if (image && internals.SliceMapper->GetInput() != image)
    {
      internals.SliceMapper->SetInputData(image);
    }
    if (image)
    {
      double range[2];
      image->GetScalarRange(range);
      const bool automatic = internals.Window <= 0;
      internals.Slice->GetProperty()->SetColorWindow(
        automatic ? std::max(range[1] - range[0], 1.0) : internals.Window);
      internals.Slice->GetProperty()->SetColorLevel(
        automatic ? 0.5 * (range[0] + range[1]) : internals.Level);
    }
    this->UpdateCamera();
    changed = true;
  }
  changed = this->UpdateIntersections() || changed;
  internals.ViewChanged = false;
  return changed;
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::UpdateCamera()
{
  vtkInternals& internals = *this->Internals;
  vtkRenderer* renderer = internals.Renderer;
  if (!renderer)
  {
    return;
  }
  const Orientation& orientation = kOrientations[internals.Orientation];
  double halfHeight = internals.FieldOfView;
  if (halfHeight <= 0)
  {
    halfHeight = 100.0;
    if (vtkImageData* image = internals.CurrentImage())
    {
      double bounds[6];
      image->GetBounds(bounds);
      double largest = 0;
      for (int i = 0; i < 3; ++i)
      {
        if (orientation.normal[i] == 0)
        {
          largest = std::max(largest, bounds[2 * i + 1] - bounds[2 * i]);
        }
      }
      halfHeight = largest > 0 ? 0.55 * largest : halfHeight;
    }
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(internals.Center);
  const double distance = orientation.cameraSide * (10.0 * halfHeight + 1000.0);
  camera->SetPosition(internals.Center[0] + distance * orientation.normal[0],
    internals.Center[1] + distance * orientation.normal[1],
    internals.Center[2] + distance * orientation.normal[2]);
  camera->SetViewUp(const_cast<double*>(orientation.viewUp));
  camera->SetParallelScale(halfHeight);
  renderer->ResetCameraClippingRange();
  camera->SetClippingRange(1.0, 2.0 * std::abs(distance));
}

//------------------------------------------------------------------------------
bool vtkROS2SliceView::UpdateIntersections()
{
  vtkInternals& internals = *this->Internals;
  bool changed = false;
  for (auto& cut : internals.Cuts)
  {
    cut.second->Seen = false;
  }
  const Orientation& orientation = kOrientations[internals.Orientation];
  vtkNew<vtkMatrix4x4> matrix;
  if (vtkROS2Scene* scene = internals.Scene)
  {
    const int count = scene->GetNumberOfNodesByClass("vtkROS2ModelNode");
    for (int i = 0; i < count; ++i)
    {
      auto* model = vtkROS2ModelNode::SafeDownCast(scene->GetNthNodeByClass(i, "vtkROS2ModelNode"));
      if (!model || !model->GetPolyData())
      {
        continue;
      }
      std::unique_ptr<ModelCut>& cut = internals.Cuts[model];
      if (!cut || cut->Model != model)
      {
        if (cut && internals.Renderer)
        {
          internals.Renderer->RemoveViewProp(cut->Actor);
        }
        cut.reset(new ModelCut);
        cut->Model = model;
        cut->Transformer->SetTransform(cut->ToWorld);
        cut->Cutter->SetInputConnection(cut->Transformer->GetOutputPort());
        cut->Cutter->SetCutFunction(internals.Plane);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(cut->Cutter->GetOutputPort());
        mapper->ScalarVisibilityOff();
        cut->Actor->SetMapper(mapper);
        cut->Actor->GetProperty()->SetLineWidth(3.0);
        cut->Actor->GetProperty()->LightingOff();
        if (internals.Renderer)
        {
          internals.Renderer->AddViewProp(cut->Actor);
        }
        changed = true;
      }
      cut->Seen = true;
      if (cut->Transformer->GetInput() != model->GetPolyData())
      {
        cut->Transformer->SetInputData(model->GetPolyData());
        changed = true;
      }
      model->GetMatrixModelToWorld(matrix);
      bool moved = false;
      for (int k = 0; k < 16 && !moved; ++k)
      {
        moved =
          matrix->GetElement(k / 4, k % 4) != cut->ToWorld->GetMatrix()->GetElement(k / 4, k % 4);
      }
      if (moved)
      {
        cut->ToWorld->SetMatrix(matrix);
        changed = true;
      }
      const double* color = model->GetColor();
      cut->Actor->GetProperty()->SetColor(color[0], color[1], color[2]);
      cut->Actor->SetVisibility(model->GetVisibility());
      const double offset = kLineOffset * orientation.cameraSide;
      cut->Actor->SetPosition(offset * orientation.normal[0], offset * orientation.normal[1],
        offset * orientation.normal[2]);
    }
  }
  for (auto it = internals.Cuts.begin(); it != internals.Cuts.end();)
  {
    if (!it->second->Seen)
    {
      if (internals.Renderer)
      {
        internals.Renderer->RemoveViewProp(it->second->Actor);
      }
      it = internals.Cuts.erase(it);
      changed = true;
    }
    else
    {
      ++it;
    }
  }
  if (changed || internals.ViewChanged)
  {
    internals.Intersected = 0;
    for (auto& cut : internals.Cuts)
    {
      cut.second->Cutter->Update();
      if (cut.second->Cutter->GetOutput()->GetNumberOfPoints() > 0 &&
        cut.second->Actor->GetVisibility())
      {
        ++internals.Intersected;
      }
    }
  }
  return changed;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkROS2SliceView::GetIntersection(vtkROS2SceneNode* modelNode) const
{
  auto it = this->Internals->Cuts.find(vtkROS2ModelNode::SafeDownCast(modelNode));
  if (it == this->Internals->Cuts.end())
  {
    return nullptr;
  }
  vtkPolyData* lines = it->second->Cutter->GetOutput();
  return lines->GetNumberOfPoints() > 0 ? lines : nullptr;
}

//------------------------------------------------------------------------------
void vtkROS2SliceView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Orientation: " << this->GetOrientation() << "\n";
  os << indent << "SliceCenter: " << this->Internals->Center[0] << " " << this->Internals->Center[1]
     << " " << this->Internals->Center[2] << "\n";
  os << indent << "IntersectedModels: " << this->Internals->Intersected << "\n";
}
