// ros2vtk — draws image subscribers (any subscriber node whose messages convert to
// vtkImageData, e.g. sensor_msgs/Image) and volume nodes (vtkROS2VolumeNode: a CT phantom, with
// its own window/level) at their pose: a 2D image as a slice (vtkImageActor)
// with window/level, a 3D one as a volume (vtkVolume, smart mapper). The pose is the node's
// "transform" reference (a tf lookup or registration), identity without one. Window and level
// come from the node's attributes "ros2vtk.display.window" / "ros2vtk.display.level" (saved
// with the scene), else from the image's scalar range (RGB images are shown as they are).
#ifndef vtkROS2ImageDisplayableManager_h
#define vtkROS2ImageDisplayableManager_h

#include "ros2vtkDisplayModule.h" // for export macro
#include "vtkROS2DisplayableManager.h"

class vtkImageActor;
class vtkVolume;

class ROS2VTKDISPLAY_EXPORT vtkROS2ImageDisplayableManager : public vtkROS2DisplayableManager
{
public:
  static vtkROS2ImageDisplayableManager* New();
  vtkTypeMacro(vtkROS2ImageDisplayableManager, vtkROS2DisplayableManager);

  bool CanDisplay(vtkROS2SceneNode* node) override;

  /// The parts of an image node's prop (a vtkPropAssembly): the slice and the volume. One of
  /// them is visible, depending on the image's depth.
  static vtkImageActor* GetImageActor(vtkProp* prop);
  static vtkVolume* GetVolume(vtkProp* prop);

protected:
  vtkROS2ImageDisplayableManager() = default;
  ~vtkROS2ImageDisplayableManager() override = default;

  vtkProp* CreateProp(vtkROS2SceneNode* node) override;
  void UpdateProp(vtkROS2SceneNode* node, vtkProp* prop) override;
  void UpdatePose(vtkROS2SceneNode* node, vtkProp* prop) override;

private:
  vtkROS2ImageDisplayableManager(const vtkROS2ImageDisplayableManager&) = delete;
  void operator=(const vtkROS2ImageDisplayableManager&) = delete;
};

#endif
