// ros2vtk — image subscribers as slices or volumes (see the header). The prop holds its own
// shallow copy of the newest image: the node's image is overwritten on later spins.
#include "vtkROS2ImageDisplayableManager.h"

#include "Internal/SubscriberData.hpp"
#include "vtkROS2SceneNode.h"
#include "vtkROS2VolumeNode.h"

#include "vtkColorTransferFunction.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkImageProperty.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdlib>

vtkStandardNewMacro(vtkROS2ImageDisplayableManager);

namespace {

bool AttributeNumber(vtkROS2SceneNode* node, const char* name, double& value)
{
  const char* text = node->GetAttribute(name);
  if (!text || !*text)
  {
    return false;
  }
  char* end = nullptr;
  const double parsed = std::strtod(text, &end);
  if (end == text)
  {
    return false;
  }
  value = parsed;
  return true;
}

}

//------------------------------------------------------------------------------
bool vtkROS2ImageDisplayableManager::CanDisplay(vtkROS2SceneNode* node)
{
  return ros2vtk::display::IsSubscriberOf(node, "vtkImageData") ||
    vtkROS2VolumeNode::SafeDownCast(node);
}

//------------------------------------------------------------------------------
vtkImageActor* vtkROS2ImageDisplayableManager::GetImageActor(vtkProp* prop)
{
  auto* assembly = vtkPropAssembly::SafeDownCast(prop);
  return assembly ? vtkImageActor::SafeDownCast(assembly->GetParts()->GetItemAsObject(0)) : nullptr;
}

//------------------------------------------------------------------------------
vtkVolume* vtkROS2ImageDisplayableManager::GetVolume(vtkProp* prop)
{
  auto* assembly = vtkPropAssembly::SafeDownCast(prop);
  return assembly ? vtkVolume::SafeDownCast(assembly->GetParts()->GetItemAsObject(1)) : nullptr;
}

//------------------------------------------------------------------------------
vtkProp* vtkROS2ImageDisplayableManager::CreateProp(vtkROS2SceneNode*)
{
  vtkNew<vtkImageData> image; // shared by slice and volume
  vtkNew<vtkImageActor> slice;
  slice->GetMapper()->SetInputData(image);
  slice->SetUserMatrix(vtkNew<vtkMatrix4x4>());
  slice->GetProperty()->SetInterpolationTypeToNearest();
  vtkNew<vtkVolume> volume;
  vtkNew<vtkSmartVolumeMapper> volumeMapper;
  volumeMapper->SetInputData(image);
  volume->SetMapper(volumeMapper);
  volume->SetUserMatrix(vtkNew<vtkMatrix4x4>());
  vtkNew<vtkVolumeProperty> volumeProperty;
  volumeProperty->ShadeOff();
  volumeProperty->SetInterpolationTypeToLinear();
  volume->SetProperty(volumeProperty);
  slice->VisibilityOff();
  volume->VisibilityOff();
  vtkPropAssembly* assembly = vtkPropAssembly::New();
  assembly->AddPart(slice);
  assembly->AddPart(volume);
  return assembly;
}

//------------------------------------------------------------------------------
void vtkROS2ImageDisplayableManager::UpdateProp(vtkROS2SceneNode* node, vtkProp* prop)
{
  vtkImageActor* slice = GetImageActor(prop);
  vtkVolume* volume = GetVolume(prop);
  auto* image = vtkImageData::SafeDownCast(slice->GetMapper()->GetInput());
  auto* volumeNode = vtkROS2VolumeNode::SafeDownCast(node);
  auto* message = volumeNode
    ? volumeNode->GetImageData()
    : vtkImageData::SafeDownCast(ros2vtk::display::LastMessageObject(node));
  if (!message || !message->GetPointData()->GetScalars() ||
    (volumeNode && !volumeNode->GetVisibility()))
  {
    slice->VisibilityOff();
    volume->VisibilityOff();
    return;
  }
  image->ShallowCopy(message);
  image->Modified();
  int dims[3];
  image->GetDimensions(dims);
  const bool is3D = dims[0] > 1 && dims[1] > 1 && dims[2] > 1;
  const int components = image->GetNumberOfScalarComponents();
  double range[2];
  image->GetScalarRange(range);
  if (components >= 3)
  {
    range[0] = 0.0;
    range[1] = 255.0;
  }
  double window = range[1] > range[0] ? range[1] - range[0] : 1.0;
  double level = 0.5 * (range[0] + range[1]);
  if (volumeNode && volumeNode->GetWindow() > 0)
  {
    window = volumeNode->GetWindow();
    level = volumeNode->GetLevel();
  }
  AttributeNumber(node, "ros2vtk.display.window", window);
  AttributeNumber(node, "ros2vtk.display.level", level);
  slice->GetProperty()->SetColorWindow(window);
  slice->GetProperty()->SetColorLevel(level);
  if (is3D)
  {
    // A grey ramp over the window, transparent below it: the volume reads like a CT rendering.
    vtkVolumeProperty* volumeProperty = volume->GetProperty();
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(level - 0.5 * window, 0.0);
    opacity->AddPoint(level + 0.5 * window, 0.8);
    vtkNew<vtkColorTransferFunction> colors;
    colors->AddRGBPoint(level - 0.5 * window, 0.0, 0.0, 0.0);
    colors->AddRGBPoint(level + 0.5 * window, 1.0, 1.0, 1.0);
    volumeProperty->SetScalarOpacity(opacity);
    volumeProperty->SetColor(colors);
    volumeProperty->SetIndependentComponents(components == 1);
  }
  slice->SetVisibility(!is3D);
  volume->SetVisibility(is3D);
}

//------------------------------------------------------------------------------
void vtkROS2ImageDisplayableManager::UpdatePose(vtkROS2SceneNode* node, vtkProp* prop)
{
  vtkMatrix4x4* matrix = GetImageActor(prop)->GetUserMatrix();
  GetParentTransformToWorld(node, matrix);
  matrix->Modified();
  GetVolume(prop)->GetUserMatrix()->DeepCopy(matrix);
}
